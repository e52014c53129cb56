"""Small LAS tiles for the GUI tests, written without any LAS library: LAS
1.2, point format 2 (26-byte records: format 0 and 16-bit Red, Green,
Blue), a gently rolling 200 m square of ground (no random numbers)."""

import math
import struct


def red_west_green_east(i, j, rows):
    """The west half of the tile pure red, the east half pure green."""
    return (65535, 0, 0) if i < rows // 2 else (0, 65535, 0)


def ground(i, j, rows):
    """ASPRS class 2 (ground) everywhere."""
    return 2


def tile_points(west, south, colors, classes, size=200.0, rows=60):
    """(position, color, class) of each point of a rows x rows grid."""
    for i in range(rows):
        for j in range(rows):
            x, y = west + size * (i + 0.5) / rows, south + size * (j + 0.5) / rows
            z = 50.0 + 3.0 * math.sin(i / 7.0) * math.cos(j / 9.0)
            yield (x, y, z), colors(i, j, rows), classes(i, j, rows)


def wkt_record(wkt):
    """A LASF_Projection WKT record (2112): its 54-byte header, then the
    null-terminated text."""
    text = wkt.encode("ascii") + b"\0"
    header = struct.pack("<H16sHH32s", 0, b"LASF_Projection", 2112, len(text), b"OGC WKT")
    return header + text


def write_tile(path, west, south, scale=0.01, colors=red_west_green_east, classes=ground, wkt=None,
               lone=None):
    """Writes the tile whose south-west corner is (west, south); with `wkt`,
    a coordinate system record; with `lone` (x, y, z), one more point there,
    far from the others."""
    points = list(tile_points(west, south, colors, classes))
    if lone:
        points.append((lone, (0, 0, 0), 2))
    records = wkt_record(wkt) if wkt else b""
    xyz = [p for p, _, _ in points]
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 2
    struct.pack_into("<HIIBHI", header, 94, 227, 227 + len(records), 1 if wkt else 0, 2, 26, len(points))
    offset = (west, south, 0.0)
    struct.pack_into("<3d3d", header, 131, scale, scale, scale, *offset)
    low = [min(p[k] for p in xyz) for k in range(3)]
    high = [max(p[k] for p in xyz) for k in range(3)]
    struct.pack_into("<6d", header, 179, high[0], low[0], high[1], low[1], high[2], low[2])
    body = b"".join(
        struct.pack("<3iHBBbBH3H", *(round((c - o) / scale) for c, o in zip(p, offset)), 0, 0x09, label, 0, 0, 0,
                    *rgb)
        for p, rgb, label in points)
    with open(path, "wb") as handle:
        handle.write(bytes(header) + records + body)
