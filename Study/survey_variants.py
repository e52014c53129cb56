"""The survey's protocol on clouds that are not uniform: its nine shapes
(../shared/survey/shapes), thinned four ways, then perturbed and scored as
survey.py does (RMSE over all points of the unsigned, sorted principal
curvatures; a point not estimated counts as k = 0), with the normals given
and estimated.

Variants (each its own random draws, none of survey.py's):
  half      every other point on average (a random half), another noise draw
  gradient  density rising tenfold across the shape's longest axis
  stripes   scan lines: bands four spacings wide, every point kept in one
            band of two, a fifth of them in the other
  seed      the whole cloud, another noise draw

usage (from the project's root, after a build):
  PYTHONPATH=build/lib/python3.11/site-packages pvpython Study/survey_variants.py \
      [--variants half,gradient] [--conditions clean,pos0.005,pos0.01] \
      [--set NormalFieldFit=1 ...] [--shapes torus,goursat]
"""
import argparse
import os
import sys

import numpy as np

SURVEY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "survey")
sys.path.insert(0, SURVEY)
import survey  # noqa: E402  (the shared protocol: clouds, noise, filter run, score)

VARIANTS = ["half", "gradient", "stripes", "seed"]


def thinned(cloud, variant, rng):
    """The indices of the points a variant keeps."""
    P = cloud["P"]
    n = len(P)
    if variant == "seed":
        return np.arange(n)
    if variant == "half":
        return np.flatnonzero(rng.random(n) < 0.5)
    spread = P.max(0) - P.min(0)
    axis = int(np.argmax(spread))
    t = (P[:, axis] - P[:, axis].min()) / spread[axis]
    if variant == "gradient":
        return np.flatnonzero(rng.random(n) < 0.1 + 0.9 * t)
    spacing = np.sqrt(4.0 * np.pi / n)  # the unit sphere's, about the shapes'
    band = np.floor(P[:, axis] / (4.0 * spacing)).astype(int) % 2 == 0
    return np.flatnonzero(band | (rng.random(n) < 0.2))


def perturbed(cloud, keep, condition, rng):
    c = survey.parse_condition(condition)
    P, N = cloud["P"][keep].copy(), cloud["N"][keep].copy()
    if c["kind"] != "noise":
        raise ValueError("variants take clean and position noise conditions: " + condition)
    G = rng.standard_normal(P.shape)
    if c["nrm"]:
        N = N + c["nrm"] * G
        N /= np.linalg.norm(N, axis=1)[:, None]
    return P + c["pos"] * G, N


def subset(cloud, keep):
    return {k: (v[keep] if isinstance(v, np.ndarray) and len(v) == len(cloud["P"]) else v)
            for k, v in cloud.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--conditions", default="clean,pos0.005,pos0.01")
    parser.add_argument("--shapes", default=",".join(survey.SHAPES))
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    args = parser.parse_args()
    for item in args.set:
        name, value = item.split("=", 1)
        survey.SETTINGS[name] = float(value) if "." in value else int(value)
    shapes = args.shapes.split(",")
    print("variant    condition       given k  estimated k   (mean over %d shapes)" % len(shapes))
    for variant in args.variants.split(","):
        for condition in args.conditions.split(","):
            scores = {"given": [], "est": []}
            for index, shape in enumerate(shapes):
                cloud = survey.load_cloud(shape)
                rng = np.random.default_rng(1000 + 17 * index + VARIANTS.index(variant))
                keep = thinned(cloud, variant, rng)
                P, N = perturbed(cloud, keep, condition, rng)
                truth = subset(cloud, keep)
                scores["given"].append(survey.score(survey.run_filter(P, N), truth)["k"])
                scores["est"].append(survey.score(survey.run_filter(P, None), truth)["k"])
            print("%-10s %-14s %8.4f %12.4f" % (variant, condition, np.mean(scores["given"]),
                                                 np.mean(scores["est"])), flush=True)


if __name__ == "__main__":
    main()
