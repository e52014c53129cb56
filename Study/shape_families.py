"""The filter's defaults on three families of clouds beyond the shared suite.

1. boxes:      rounded boxes (a 10 x 7 x 5 half-size box's Minkowski sum with a
               ball of radius rho = 5, 10 or 20 point spacings): flat faces,
               quarter-cylinder fillets and eighth-sphere corners, scored
               separately; 50k points, position noise 0, 0.1 h and 0.5 h.
2. structured: the suite's ellipsoid 10 / 7 / 4 and torus 10 / 3 (20k, 50k
               points) with positions
               rounded to a grid of h / 3 (a structured error), beside Gaussian
               noise of the same RMS (0.096 h per axis).
3. scanlines:  a sphere R = 10 and the suite's paraboloid patch sampled along
               parallel lines, 12 times denser along the lines than across
               them (h_along = g / 12, g the gap between lines, about 3 h),
               like a lidar; about 2.5k and 20k points, noise 0 and 0.1 h.

Every cloud is given with its exact normals ("exact") and without normals, the
filter estimating them ("estimated", SetNormalsSourceToEstimated()). The
conventions are the shared suite's (../shared/accuracy/README.md): points
uniform by area (families 1, 2), h = sqrt(area / N), isotropic Gaussian
noise of sigma = noise x h per axis, the normals those of the clean sample,
curvature positive where the surface bends away from the normal (a sphere with
outward normals has k = +1/R; checked against the filter at start-up). Where
the filter estimates the normals, the exact curvatures are turned to the side
of its normal (orientation is not what is measured).

Scores, over the scored points of a part (family 1) or a shape (2, 3); K is
the largest |k| (1/rho for the boxes, the shape's for the others):
  valid      share of points with Curvature_Valid = 1
  e_min, e_max   mean |k_min - exact|, mean |k_max - exact| over the valid,
             in units of K; err = the larger (the suite's relative error)
  <=2SE      share of the valid whose error max(|dk_min|, |dk_max|) is at most
             2 x Curvature_Standard_Error
  err/SE     median of that error / Curvature_Standard_Error
  off>20%    share of the valid whose error exceeds 0.2 K
  max        the largest error of a valid point, in K
  dir        median angle (degrees) between the estimated and exact maximum
             directions, as lines, where exact k_max - k_min > 0.05 K
  s/h        median Surroundings_Threshold (the radius used), in spacings h
  n_deg      where the filter estimates the normals: median angle (degrees)
             between its normals and the exact ones, as lines
  inside     (boxes) share of scored points whose radius s stays within the
             part (distance to the part's border > s)
  err_in, off_in   (boxes) err and off>20% over the valid points of those
Scored points: boxes, the points whose Euclidean distance to the nearest
border of their part is more than MARGIN_SPACINGS (3) spacings h, a fixed
margin (twice the radius would leave no fillet point at rho = 5 h); the
paraboloid patch, the points farther than their own radius s from the
patch's border (parameter distance, a lower bound; 2 s would leave a dozen
points of the 2.5k cloud); closed shapes, all.

Run (one family at a time with --family: on 2 shared cores, boxes about 6
minutes, or one fillet radius at a time with --rho 5; structured about 5;
scanlines about 1.5):

    export PYTHONPATH=/work/main/build/lib/python3.11/site-packages
    export VTK_SMP_BACKEND_IN_USE=STDThread
    nice /usr/bin/python3 Study/shape_families.py [--family boxes|structured|scanlines] [--quick]

--quick: a small subset of each family (rho = 10 h at 30k points, 20k-point
smooth shapes, 2.5k-point scan lines), about a minute.
--check: only the generator checks and the filter's sign check.
Seeds are fixed (SEED + a per-cloud offset): every run gives the same clouds.
"""

import argparse
import datetime
import math
import os
import subprocess
import sys

import numpy
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from principal_curvatures import vtkPrincipalCurvatureEstimation

SEED = 20261202
MARGIN_SPACINGS = 3.0
BOX_HALF = (10.0, 7.0, 5.0)
ELLIPSOID = (10.0, 7.0, 4.0)
TORUS = (10.0, 3.0)
SPHERE_R = 10.0
PARABOLOID = (6.0, 12.0, 10.0)     # z = x^2 / (2 * 6) + y^2 / (2 * 12) on [-10, 10]^2
SCAN_RATIO = 12.0                  # gap between lines / spacing along a line (3 h / (h / 4))
GRID_FRACTION = 1.0 / 3.0          # the structured error: positions rounded to h / 3
PART_NAMES = ("face", "fillet", "corner")


# ----------------------------------------------------------------------------
# Clouds: dict with points (clean), normals, kmin, kmax, dmax (unit k_max
# direction, zero where umbilic), border (distance to the nearest part or
# patch border, inf if none), part (0 face, 1 fillet, 2 corner; or 0), K, h.
# ----------------------------------------------------------------------------

def unit_rows(v):
    return v / numpy.linalg.norm(v, axis=1, keepdims=True)


def make_cloud(points, normals, kmin, kmax, dmax, K, h, border=None, part=None):
    n = len(points)
    return {"points": points, "normals": normals, "kmin": kmin, "kmax": kmax, "dmax": dmax, "K": K, "h": h,
            "border": numpy.full(n, numpy.inf) if border is None else border,
            "part": numpy.zeros(n, dtype=int) if part is None else part}


# --- family 1: rounded boxes -------------------------------------------------

def box_area(rho, half=BOX_HALF):
    a, b, c = half
    return 8 * (a * b + b * c + c * a) + 4 * math.pi * rho * (a + b + c) + 4 * math.pi * rho ** 2


def box_spacing(spacings, n, half=BOX_HALF):
    """h with h = sqrt(area(rho) / n) and rho = spacings x h: the positive root of
    h^2 (n - 4 pi m^2) - 4 pi m (a + b + c) h - 8 (ab + bc + ca) = 0."""
    a, b, c = half
    qa, qb, qc = n - 4 * math.pi * spacings ** 2, -4 * math.pi * spacings * (a + b + c), -8 * (a * b + b * c + c * a)
    return (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)


def box_parts(rho, half=BOX_HALF):
    """(kind, area, parameters) of the 6 faces, 12 fillets and 8 corners."""
    parts = []
    for i in range(3):
        j, k = (i + 1) % 3, (i + 2) % 3
        for s in (-1.0, 1.0):
            parts.append(("face", 4 * half[j] * half[k], (i, s)))
        for sj in (-1.0, 1.0):
            for sk in (-1.0, 1.0):
                parts.append(("fillet", math.pi * rho * half[i], (i, sj, sk)))
    for sx in (-1.0, 1.0):
        for sy in (-1.0, 1.0):
            for sz in (-1.0, 1.0):
                parts.append(("corner", math.pi * rho ** 2 / 2, (sx, sy, sz)))
    return parts


def sample_face(rng, m, rho, half, i, s):
    j, k = (i + 1) % 3, (i + 2) % 3
    p = numpy.zeros((m, 3))
    p[:, i] = s * (half[i] + rho)
    p[:, j] = rng.uniform(-half[j], half[j], m)
    p[:, k] = rng.uniform(-half[k], half[k], m)
    n = numpy.zeros((m, 3))
    n[:, i] = s
    border = numpy.minimum(half[j] - numpy.abs(p[:, j]), half[k] - numpy.abs(p[:, k]))
    zero = numpy.zeros(m)
    return p, n, zero, zero, numpy.zeros((m, 3)), border


def sample_fillet(rng, m, rho, half, i, sj, sk):
    """Quarter cylinder along axis i at the edge (sj b_j, sk b_k); theta from face j to face k."""
    j, k = (i + 1) % 3, (i + 2) % 3
    t = rng.uniform(-half[i], half[i], m)
    theta = rng.uniform(0, math.pi / 2, m)
    n = numpy.zeros((m, 3))
    n[:, j], n[:, k] = sj * numpy.cos(theta), sk * numpy.sin(theta)
    p = rho * n
    p[:, i] += t
    p[:, j] += sj * half[j]
    p[:, k] += sk * half[k]
    dmax = numpy.zeros((m, 3))
    dmax[:, j], dmax[:, k] = -sj * numpy.sin(theta), sk * numpy.cos(theta)
    chord = 2 * rho * numpy.sin(numpy.minimum(theta, math.pi / 2 - theta) / 2)
    border = numpy.minimum(half[i] - numpy.abs(t), chord)
    return p, n, numpy.zeros(m), numpy.full(m, 1 / rho), dmax, border


def sample_corner(rng, m, rho, half, sx, sy, sz):
    signs = numpy.array([sx, sy, sz])
    n = numpy.abs(unit_rows(rng.standard_normal((m, 3)))) * signs
    p = numpy.array(half) * signs + rho * n
    # chord to the nearest of the three quarter circles bounding the octant
    chord = 2 * rho * numpy.sin(numpy.arcsin(numpy.clip(numpy.abs(n).min(axis=1), 0, 1)) / 2)
    return p, n, numpy.full(m, 1 / rho), numpy.full(m, 1 / rho), numpy.zeros((m, 3)), chord


def rounded_box(rng, n, spacings, half=BOX_HALF):
    """n points uniform by area on the rounded box with rho = spacings x h."""
    h = box_spacing(spacings, n, half)
    rho = spacings * h
    parts = box_parts(rho, half)
    areas = numpy.array([area for _, area, _ in parts])
    counts = rng.multinomial(n, areas / areas.sum())
    samplers = {"face": sample_face, "fillet": sample_fillet, "corner": sample_corner}
    pieces, labels = [], []
    for (kind, _, args), m in zip(parts, counts):
        pieces.append(samplers[kind](rng, m, rho, half, *args))
        labels.append(numpy.full(m, PART_NAMES.index(kind)))
    p, nn, kmin, kmax, dmax, border = (numpy.concatenate(column) for column in zip(*pieces))
    cloud = make_cloud(p, nn, kmin, kmax, dmax, 1 / rho, h, border, numpy.concatenate(labels))
    cloud["rho"] = rho
    return cloud


# --- smooth shapes: implicit ground truth (as the shared suite) --------------

def shape_operator(gradient, hessian):
    """Unit normals along the gradient, principal curvatures (ascending) and the k_max
    direction of S = P H P / |grad| on the tangent plane."""
    norm = numpy.linalg.norm(gradient, axis=1)
    n = gradient / norm[:, None]
    axis = numpy.where(numpy.abs(n[:, :1]) < 0.9, numpy.array([[1.0, 0, 0]]), numpy.array([[0, 1.0, 0]]))
    t1 = unit_rows(numpy.cross(n, axis))
    t2 = numpy.cross(n, t1)
    frame = numpy.stack([t1, t2], 2)
    m = numpy.einsum("nia,nij,njb->nab", frame, hessian, frame) / norm[:, None, None]
    w, v = numpy.linalg.eigh(m)
    dmax = numpy.einsum("nia,na->ni", frame, v[:, :, 1])
    dmax[numpy.abs(w[:, 1] - w[:, 0]) < 1e-12] = 0
    return n, w[:, 0], w[:, 1], dmax


def ellipsoid_truth(p, axes=ELLIPSOID):
    d = 1 / numpy.array(axes) ** 2
    hessian = numpy.broadcast_to(2 * numpy.diag(d), (len(p), 3, 3)).copy()
    return shape_operator(2 * p * d, hessian)


def torus_truth(p, radii=TORUS):
    big = radii[0]
    x, y, z = p.T
    r = numpy.hypot(x, y)
    g = numpy.stack([2 * (r - big) * x / r, 2 * (r - big) * y / r, 2 * z], 1)
    hess = numpy.zeros((len(p), 3, 3))
    hess[:, 0, 0] = 2 * (1 - big / r + big * x * x / r ** 3)
    hess[:, 1, 1] = 2 * (1 - big / r + big * y * y / r ** 3)
    hess[:, 0, 1] = hess[:, 1, 0] = 2 * big * x * y / r ** 3
    hess[:, 2, 2] = 2
    return shape_operator(g, hess)


def paraboloid_truth(p, shape=PARABOLOID):
    """F = z - f(x, y), normal +z: the paraboloid bends towards it, k < 0."""
    pa, pb, _ = shape
    g = numpy.stack([-p[:, 0] / pa, -p[:, 1] / pb, numpy.ones(len(p))], 1)
    hess = numpy.zeros((len(p), 3, 3))
    hess[:, 0, 0], hess[:, 1, 1] = -1 / pa, -1 / pb
    return shape_operator(g, hess)


def rejection(rng, n, propose, accept):
    out, have = [], 0
    while have < n:
        candidates = propose(int((n - have) * 1.5) + 1000)
        candidates = candidates[rng.random(len(candidates)) < accept(candidates)]
        out.append(candidates)
        have += len(candidates)
    return numpy.concatenate(out)[:n]


def ellipsoid_area_density(u, axes=ELLIPSOID):
    a, b, c = axes
    return numpy.sqrt((b * c * u[:, 0]) ** 2 + (a * c * u[:, 1]) ** 2 + (a * b * u[:, 2]) ** 2)


def ellipsoid_area(axes=ELLIPSOID, m=1000):
    ct = (numpy.arange(m) + 0.5) / m * 2 - 1
    ph = (numpy.arange(2 * m) + 0.5) / (2 * m) * 2 * math.pi
    c, f = numpy.meshgrid(ct, ph, indexing="ij")
    st = numpy.sqrt(1 - c ** 2)
    u = numpy.stack([st * numpy.cos(f), st * numpy.sin(f), c], -1).reshape(-1, 3)
    return float(ellipsoid_area_density(u, axes).mean() * 4 * math.pi)


def ellipsoid(rng, n, axes=ELLIPSOID):
    a, b, c = axes
    top = max(a * b, a * c, b * c)
    u = rejection(rng, n, lambda m: unit_rows(rng.standard_normal((m, 3))),
                  lambda q: ellipsoid_area_density(q, axes) / top)
    p = u * numpy.array(axes)
    return make_cloud(p, *ellipsoid_truth(p, axes), K=a / c ** 2, h=math.sqrt(ellipsoid_area(axes) / n))


def torus(rng, n, radii=TORUS):
    big, small = radii

    def propose(m):
        return rng.uniform(0, 2 * math.pi, (m, 2))

    uv = rejection(rng, n, propose, lambda q: (big + small * numpy.cos(q[:, 1])) / (big + small))
    r = big + small * numpy.cos(uv[:, 1])
    p = numpy.stack([r * numpy.cos(uv[:, 0]), r * numpy.sin(uv[:, 0]), small * numpy.sin(uv[:, 1])], 1)
    return make_cloud(p, *torus_truth(p, radii), K=1 / small, h=math.sqrt(4 * math.pi ** 2 * big * small / n))


# --- family 3: scan lines ----------------------------------------------------

def line_samples(rng, length, step):
    """Equally spaced positions along [0, length) with a random phase."""
    count = max(int(round(length / step)), 1)
    return (rng.random() + numpy.arange(count)) * (length / count)


def scan_sphere(rng, n, radius=SPHERE_R):
    """Circles x = const, gap g across (in x), arc spacing g / SCAN_RATIO along. The
    circles' total length is pi^2 R^2 / g = (pi / 4) area / g: g from that, for about n."""
    area = 4 * math.pi * radius ** 2
    gap = math.sqrt(SCAN_RATIO * math.pi / 4 * area / n)
    lines = int(round(2 * radius / gap))
    xs = -radius + (rng.random() + numpy.arange(lines)) * (2 * radius / lines)
    pieces = []
    for x in xs:
        r = math.sqrt(radius ** 2 - x ** 2)
        phi = line_samples(rng, 2 * math.pi * r, gap / SCAN_RATIO) / r + rng.uniform(0, 2 * math.pi)
        pieces.append(numpy.stack([numpy.full(len(phi), x), r * numpy.cos(phi), r * numpy.sin(phi)], 1))
    p = numpy.concatenate(pieces)
    nn = p / radius
    k = numpy.full(len(p), 1 / radius)
    cloud = make_cloud(p, nn, k, k, numpy.zeros_like(p), 1 / radius, math.sqrt(area / len(p)))
    cloud["gap"] = gap
    return cloud


def paraboloid_area(shape=PARABOLOID, m=2000):
    pa, pb, half = shape
    t = (numpy.arange(m) + 0.5) / m * 2 * half - half
    x, y = numpy.meshgrid(t, t, indexing="ij")
    return float(numpy.sqrt(1 + (x / pa) ** 2 + (y / pb) ** 2).mean() * (2 * half) ** 2)


def scan_paraboloid(rng, n, shape=PARABOLOID):
    """Lines y = const (gap g), along x at spacing g / SCAN_RATIO (uniform in x, as a
    scanner's uniform angle nearly is)."""
    pa, pb, half = shape
    area = paraboloid_area(shape)
    gap = math.sqrt(SCAN_RATIO * (2 * half) ** 2 / n)     # spacings in the parameter plane
    lines = int(round(2 * half / gap))
    ys = -half + (rng.random() + numpy.arange(lines)) * (2 * half / lines)
    pieces = []
    for y in ys:
        x = line_samples(rng, 2 * half, gap / SCAN_RATIO) - half
        pieces.append(numpy.stack([x, numpy.full(len(x), y)], 1))
    xy = numpy.concatenate(pieces)
    p = numpy.column_stack([xy, xy[:, 0] ** 2 / (2 * pa) + xy[:, 1] ** 2 / (2 * pb)])
    border = numpy.minimum(half - numpy.abs(xy[:, 0]), half - numpy.abs(xy[:, 1]))
    cloud = make_cloud(p, *paraboloid_truth(p, shape), K=1 / pa, h=math.sqrt(area / len(p)), border=border)
    cloud["gap"] = gap
    return cloud


# --- perturbations -----------------------------------------------------------

def gaussian_noise(rng, cloud, sigma_spacings):
    return cloud["points"] + sigma_spacings * cloud["h"] * rng.standard_normal(cloud["points"].shape)


def grid_rounded(cloud, fraction=GRID_FRACTION):
    step = fraction * cloud["h"]
    return numpy.round(cloud["points"] / step) * step


# ----------------------------------------------------------------------------
# Checks
# ----------------------------------------------------------------------------

def check_generator(cloud, name, samples=40, seed=SEED):
    """Assert on a few samples: unit normals; k_max directions unit and tangent where
    anisotropic; the cloud's neighbors q of p lie on the surface as the normal and
    curvatures say: the chord's normal curvature -2 (q - p).n / |q - p|^2 matches Euler's
    k_min + (k_max - k_min) cos^2(angle to d_max) within 0.1 K (second order in |q - p| K
    <= 0.35), which also checks the sign convention (a sphere: +1/R)."""
    p, n, K = cloud["points"], cloud["normals"], cloud["K"]
    assert numpy.allclose(numpy.linalg.norm(n, axis=1), 1, atol=1e-9), name + ": normals not unit"
    aniso = cloud["kmax"] - cloud["kmin"] > 1e-9
    d = cloud["dmax"][aniso]
    assert numpy.allclose(numpy.linalg.norm(d, axis=1), 1, atol=1e-9), name + ": k_max directions not unit"
    assert numpy.allclose(numpy.sum(d * n[aniso], axis=1), 0, atol=1e-9), name + ": k_max directions not tangent"
    radius = 0.35 / K
    rng = numpy.random.default_rng(seed)
    tree = cKDTree(p)
    candidates = numpy.nonzero(cloud["border"] > radius)[0]
    checked = 0
    for i in rng.choice(candidates, min(samples, len(candidates)), replace=False):
        near = [j for j in tree.query_ball_point(p[i], radius) if numpy.linalg.norm(p[j] - p[i]) > radius / 4]
        if len(near) < 3:
            continue
        offset = p[near] - p[i]
        height = offset @ n[i]
        dist2 = numpy.sum(offset ** 2, axis=1)
        chord_k = -2 * height / dist2
        tangent = unit_rows(offset - height[:, None] * n[i])
        euler = cloud["kmin"][i] + (cloud["kmax"][i] - cloud["kmin"][i]) * (tangent @ cloud["dmax"][i]) ** 2
        worst = numpy.max(numpy.abs(chord_k - euler))
        assert worst < 0.1 * K, "%s: point %d: normal curvature off by %.3g K" % (name, i, worst / K)
        checked += 1
    assert checked >= samples // 4, "%s: only %d points checked" % (name, checked)
    return checked


def check_sign_with_filter():
    """The filter on a noise-free sphere R = 10 with outward normals must give +0.1."""
    rng = numpy.random.default_rng(SEED)
    n = unit_rows(rng.standard_normal((20000, 3)))
    out = run_filter(SPHERE_R * n, n)
    for name in ("kmin", "kmax"):
        value = numpy.nanmedian(out[name])
        assert abs(value - 1 / SPHERE_R) < 1e-3 / SPHERE_R, "filter's sign: %s = %g on a sphere R = 10" % (name, value)


def run_checks():
    rng = numpy.random.default_rng(SEED + 99)
    for spacings in (5, 20):
        box = rounded_box(rng, 200000, spacings)
        check_generator(box, "rounded box %d h" % spacings)
        for part in range(3):
            assert numpy.sum(box["part"] == part) > 0
    check_generator(ellipsoid(rng, 100000), "ellipsoid")
    check_generator(torus(rng, 100000), "torus")
    check_generator(scan_sphere(rng, 20000), "scan-line sphere")
    check_generator(scan_paraboloid(rng, 20000), "scan-line paraboloid")
    check_sign_with_filter()
    print("generator checks and the filter's sign check passed", file=sys.stderr)


# ----------------------------------------------------------------------------
# The filter and the scores
# ----------------------------------------------------------------------------

def polydata(points, normals=None):
    cloud = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points, dtype=float), deep=True))
    cloud.SetPoints(vtk_points)
    if normals is not None:
        array = numpy_to_vtk(numpy.ascontiguousarray(normals, dtype=float), deep=True)
        array.SetName("Normals")
        cloud.GetPointData().SetNormals(array)
    return cloud


def run_filter(points, normals=None):
    """The filter's defaults; without normals, SetNormalsSourceToEstimated(). Returns the
    arrays the scores need (missing ones as NaN)."""
    curvatures = vtkPrincipalCurvatureEstimation()
    curvatures.GlobalWarningDisplayOff()
    curvatures.SetInputData(polydata(points, normals))
    if normals is None:
        curvatures.SetNormalsSourceToEstimated()
    curvatures.Update()
    pd = curvatures.GetOutput().GetPointData()

    def get(name, components=1):
        array = pd.GetArray(name)
        if array is None:
            return numpy.full((len(points), components) if components > 1 else len(points), numpy.nan)
        return vtk_to_numpy(array).astype(float)

    out = {"kmin": get("Minimum_Curvature"), "kmax": get("Maximum_Curvature"),
           "se": get("Curvature_Standard_Error"), "valid": get("Curvature_Valid") == 1,
           "trusted": get("Curvature_Trusted") == 1,
           "s": get("Surroundings_Threshold"), "dmax": get("Maximum_Curvature_Direction", 3),
           "normals": get("Normals", 3) if normals is None else None}
    out["valid"] &= numpy.isfinite(out["kmin"]) & numpy.isfinite(out["kmax"])
    return out


def exact_on_filter_side(cloud, out):
    """Exact (k_min, k_max, d_max), turned to the side of the filter's own normal where
    it estimated one pointing the other way."""
    kmin, kmax, dmax = cloud["kmin"], cloud["kmax"], cloud["dmax"]
    if out["normals"] is None:
        return kmin, kmax, dmax, 0.0
    flip = numpy.sum(out["normals"] * cloud["normals"], axis=1) < 0
    dmin = numpy.cross(cloud["normals"], dmax)
    return (numpy.where(flip, -kmax, kmin), numpy.where(flip, -kmin, kmax),
            numpy.where(flip[:, None], dmin, dmax), float(numpy.mean(flip)))


def score(cloud, out, mask):
    """The scores of the module's docstring over the points of mask."""
    kmin, kmax, dmax, flipped = exact_on_filter_side(cloud, out)
    K = cloud["K"]
    valid = out["valid"] & mask
    result = {"scored": int(mask.sum()), "valid": float(valid.sum() / max(mask.sum(), 1)), "flipped": flipped}
    nan_keys = ("e_min", "e_max", "err", "le2se", "err_se", "off20", "max", "dir", "s_h", "inside", "n_deg",
                "err_in", "off_in", "trusted", "off20_t")
    if not valid.any():
        result.update({key: math.nan for key in nan_keys})
        return result
    dk_min = numpy.abs(out["kmin"][valid] - kmin[valid])
    dk_max = numpy.abs(out["kmax"][valid] - kmax[valid])
    error = numpy.maximum(dk_min, dk_max)
    se = out["se"][valid]
    with numpy.errstate(divide="ignore", invalid="ignore"):
        ratio = numpy.where(error == 0, 0.0, error / se)
    result.update({"e_min": dk_min.mean() / K, "e_max": dk_max.mean() / K})
    result["err"] = max(result["e_min"], result["e_max"])
    result["le2se"] = float(numpy.mean(error <= 2 * se)) if numpy.isfinite(se).any() else math.nan
    result["err_se"] = float(numpy.median(ratio)) if numpy.isfinite(se).any() else math.nan
    result["off20"] = float(numpy.mean(error > 0.2 * K))
    # Curvature_Trusted: the share of valid points trusted, and the share of
    # valid points that are trusted and off by more than 0.2 K.
    trusted = out["trusted"][valid]
    result["trusted"] = float(numpy.mean(trusted))
    result["off20_t"] = float(numpy.mean(trusted & (error > 0.2 * K)))
    result["max"] = float(error.max() / K)
    aniso = valid & (cloud["kmax"] - cloud["kmin"] > 0.05 * K)
    result["dir"] = math.nan
    if aniso.any():
        dots = numpy.abs(numpy.sum(out["dmax"][aniso] * dmax[aniso], axis=1))
        result["dir"] = float(numpy.median(numpy.degrees(numpy.arccos(numpy.clip(dots, 0, 1)))))
    result["s_h"] = float(numpy.median(out["s"][valid])) / cloud["h"]
    result["inside"] = float(numpy.mean(cloud["border"][mask] > out["s"][mask]))
    result["n_deg"] = math.nan
    if out["normals"] is not None:
        dots = numpy.abs(numpy.sum(out["normals"][valid] * cloud["normals"][valid], axis=1))
        result["n_deg"] = float(numpy.median(numpy.degrees(numpy.arccos(numpy.clip(dots, 0, 1)))))
    inside = (cloud["border"] > out["s"])[valid]
    result["err_in"] = result["off_in"] = math.nan
    if inside.any():
        result["err_in"] = max(dk_min[inside].mean(), dk_max[inside].mean()) / K
        result["off_in"] = float(numpy.mean(error[inside] > 0.2 * K))
    return result


# ----------------------------------------------------------------------------
# The families
# ----------------------------------------------------------------------------

NORMALS = ("exact", "estimated")


def run_both_normals(cloud, points, label, masks):
    """Rows for the exact and the estimated normals; masks: (name, function of out) pairs."""
    rows = []
    for normals in NORMALS:
        out = run_filter(points, cloud["normals"] if normals == "exact" else None)
        for name, mask in masks:
            row = dict(label, normals=normals, part=name)
            row.update(score(cloud, out, mask(out)))
            rows.append(row)
    return rows


def family_boxes(quick, fillets=(5, 10, 20)):
    n = 30000 if quick else 50000
    rows = []
    for spacings in (10,) if quick else fillets:
        rng = numpy.random.default_rng(SEED + spacings)
        box = rounded_box(rng, n, spacings)
        eps = rng.standard_normal(box["points"].shape)
        away = box["border"] > MARGIN_SPACINGS * box["h"]
        masks = [(PART_NAMES[part], lambda out, part=part: away & (box["part"] == part)) for part in range(3)]
        for noise in ((0.0, 0.5) if quick else (0.0, 0.1, 0.5)):
            points = box["points"] + noise * box["h"] * eps
            label = {"rho": "%d h" % spacings, "noise": "%g h" % noise, "N": n}
            rows += run_both_normals(box, points, label, masks)
            print("boxes rho %d h noise %g done" % (spacings, noise), file=sys.stderr, flush=True)
    return rows


def family_structured(quick):
    rows = []
    sizes = (20000,) if quick else (20000, 50000)
    rms = GRID_FRACTION / math.sqrt(12)           # per axis, of the rounding error, in h
    for si, (shape, make) in enumerate((("ellipsoid", ellipsoid), ("torus", torus))):
        for ni, n in enumerate(sizes):
            rng = numpy.random.default_rng(SEED + 100 + 10 * si + ni)
            cloud = make(rng, n)
            perturbations = [("grid h/3", grid_rounded(cloud))]
            if not quick:
                perturbations.append(("gauss %.3f h" % rms, gaussian_noise(rng, cloud, rms)))
            for perturbation, points in perturbations:
                label = {"shape": shape, "N": n, "positions": perturbation}
                rows += run_both_normals(cloud, points, label, [("all", lambda out: numpy.ones(n, bool))])
            print("structured %s %d done" % (shape, n), file=sys.stderr, flush=True)
    return rows


def family_scanlines(quick):
    rows = []
    sizes = (2500,) if quick else (2500, 20000)
    for si, (shape, make) in enumerate((("sphere", scan_sphere), ("paraboloid", scan_paraboloid))):
        for ni, n in enumerate(sizes):
            rng = numpy.random.default_rng(SEED + 200 + 10 * si + ni)
            cloud = make(rng, n)
            eps = rng.standard_normal(cloud["points"].shape)

            def inner(out, cloud=cloud):
                # unestimated points (no radius) are scored with the median radius
                finite = numpy.isfinite(out["s"])
                s = numpy.where(finite, out["s"], numpy.median(out["s"][finite]) if finite.any() else 0.0)
                return cloud["border"] > s

            for noise in ((0.1,) if quick else (0.0, 0.1)):
                points = cloud["points"] + noise * cloud["h"] * eps
                label = {"shape": shape, "N": len(points), "gap": "%.2f h" % (cloud["gap"] / cloud["h"]),
                         "noise": "%g h" % noise}
                rows += run_both_normals(cloud, points, label, [("all", inner)])
            print("scanlines %s %d done" % (shape, n), file=sys.stderr, flush=True)
    return rows


FAMILIES = {"boxes": family_boxes, "structured": family_structured, "scanlines": family_scanlines}
LABELS = {"boxes": ("rho", "noise", "normals", "part"),
          "structured": ("shape", "N", "positions", "normals"),
          "scanlines": ("shape", "N", "gap", "noise", "normals")}
SCORES = (("scored", "%d"), ("valid", "%.3f"), ("e_min", "%.4f"), ("e_max", "%.4f"), ("err", "%.4f"),
          ("le2se", "%.3f"), ("err_se", "%.2f"), ("off20", "%.4f"), ("trusted", "%.3f"), ("off20_t", "%.4f"), ("max", "%.3g"), ("dir", "%.2f"), ("n_deg", "%.2f"), ("s_h", "%.2f"))


def table(family, rows):
    columns = list(LABELS[family])
    scores = list(SCORES) + ([("inside", "%.2f"), ("err_in", "%.4f"), ("off_in", "%.4f")]
                             if family == "boxes" else [])
    lines = ["| " + " | ".join(columns + [name for name, _ in scores]) + " |",
             "|" + "---|" * (len(columns) + len(scores))]
    for row in rows:
        cells = [str(row[c]) for c in columns]
        for name, fmt in scores:
            value = row[name]
            cells.append("-" if isinstance(value, float) and math.isnan(value) else fmt % value)
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def build_stamp():
    """The filter module's file and modification time (the build may change under a run)."""
    import principal_curvatures
    folder = os.path.dirname(principal_curvatures.__file__)
    modules = [os.path.join(folder, name) for name in os.listdir(folder) if ".so" in name]
    latest = max(modules, key=os.path.getmtime) if modules else principal_curvatures.__file__
    stamp = datetime.datetime.fromtimestamp(os.path.getmtime(latest), datetime.timezone.utc)
    return "%s of %s UTC" % (latest, stamp.strftime("%Y-%m-%d %H:%M:%S"))


def build_description():
    try:
        head = subprocess.run(["git", "-C", "/work/main", "log", "-1", "--format=%h"], capture_output=True,
                              text=True, timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        head = "?"
    return "run %s UTC; build %s (main's HEAD %s, plus any uncommitted work)" % (
        datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M"), build_stamp(), head or "?")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--family", choices=sorted(FAMILIES), action="append", help="repeatable; default all")
    parser.add_argument("--quick", action="store_true", help="one small setting per family")
    parser.add_argument("--check", action="store_true", help="only the generator and sign checks")
    parser.add_argument("--rho", type=lambda text: tuple(int(v) for v in text.split(",")),
                        help="boxes: the fillet radii in spacings, e.g. 5,10 (default 5,10,20)")
    arguments = parser.parse_args(argv)
    run_checks()
    if arguments.check:
        return
    stamp = build_stamp()
    print(build_description() + "\n")
    for family in arguments.family or list(FAMILIES):
        extra = {"fillets": arguments.rho} if family == "boxes" and arguments.rho else {}
        rows = FAMILIES[family](arguments.quick, **extra)
        print("### %s\n\n%s\n" % (family, table(family, rows)), flush=True)
    if build_stamp() != stamp:
        print("WARNING: the build changed during the run (now %s; the run used the one loaded at its start)"
              % build_stamp(), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
