"""Writes the fuzz target's seeds for the LAS and PLY parsers into
Testing/Fuzz/corpus (reader-*): small valid files of several versions,
formats and encodings, each behind the byte that routes it (251 LAS, 252
PLY). Run with any Python 3 from the repository root:

    python3 Testing/Fuzz/make_reader_seeds.py
"""

import os
import struct

CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
RECORD_LENGTHS = {0: 20, 1: 28, 2: 26, 3: 34, 6: 30, 7: 36, 8: 38}


def las(minor, point_format, count=2, extra=0, vlr=0):
    header_size = {2: 227, 3: 235, 4: 375}[minor]
    length = RECORD_LENGTHS[point_format] + extra
    header = bytearray(header_size)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, minor
    struct.pack_into("<HIIBHI", header, 94, header_size, header_size + vlr, 1 if vlr else 0, point_format,
                     length, count)
    struct.pack_into("<3d3d", header, 131, 0.001, 0.001, 0.01, 596000.0, 243000.0, 0.0)
    if minor >= 4:
        struct.pack_into("<Q", header, 247, count)
    records = b""
    for i in range(count):
        record = bytearray(length)
        struct.pack_into("<iiiH", record, 0, 700123 + i, -5 * i, 8025, 1000 + i)
        record[14], record[15], record[16] = 0x39 if point_format < 6 else 0xC9, 0xF2, 200
        records += bytes(record)
    return bytes([251]) + bytes(header) + b"\x11" * vlr + records


def vlr(user, record_id, payload):
    return struct.pack("<H16sHH32s", 0, user, record_id, len(payload), b"") + payload


def extra_bytes_descriptor(data_type, options, name, scale=0.0, offset=0.0):
    descriptor = bytearray(192)
    descriptor[2], descriptor[3] = data_type, options
    descriptor[4:4 + len(name)] = name
    struct.pack_into("<d", descriptor, 112, scale)
    struct.pack_into("<d", descriptor, 136, offset)
    return bytes(descriptor)


def las_with_records():
    """LAS 1.4 format 6 with the records the reader interprets: GeoTIFF keys
    with their ASCII parameters, WKT, and an Extra Bytes record (a scaled
    unsigned short, a float, an undocumented byte)."""
    keys = struct.pack("<16H", 1, 1, 0, 3, 1024, 0, 1, 1, 3072, 0, 1, 2231, 3073, 34737, 6, 0)
    records = (vlr(b"LASF_Projection", 34735, keys) + vlr(b"LASF_Projection", 34737, b"name|\0") +
               vlr(b"LASF_Projection", 2112,
                   b'COMPD_CS["c",PROJCS["p",UNIT["US survey foot",0.3048006096012192]],'
                   b'VERT_CS["v",UNIT["foot",0.3048]]]\0') +
               vlr(b"LASF_Spec", 4, extra_bytes_descriptor(3, 0x18, b"Scaled", 0.01, 5.0) +
                   extra_bytes_descriptor(9, 0, b"Value") + extra_bytes_descriptor(0, 1, b"")))
    seed = bytearray(las(4, 6, extra=7, vlr=len(records)))
    seed[1 + 375:1 + 375 + len(records)] = records
    struct.pack_into("<I", seed, 1 + 100, 4)
    return bytes(seed)


def ply(body_format, point_type="double"):
    header = ("ply\nformat %s 1.0\nelement vertex 2\nproperty %s x\nproperty %s y\nproperty %s z\n"
              "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n"
              "property uchar green\nproperty uchar blue\nproperty int label\n"
              "property list uchar int indices\nelement face 1\nproperty list uchar int vertex_indices\n"
              "end_header\n" % ((body_format,) + (point_type,) * 3))
    code = "d" if point_type == "double" else "f"
    if body_format == "ascii":
        body = "596700.123 243650.5 80 0 0 1 255 0 10 7 2 0 1\n-1 2 -3 0.6 0 0.8 1 2 3 -3 0\n3 0 1 0\n"
        return bytes([252]) + (header + body).encode("ascii")
    order = "<" if body_format == "binary_little_endian" else ">"
    body = b""
    for i in range(2):
        body += struct.pack(order + "3%s3f3BiBi" % code, 596700.123 + i, 243650.5, 80.0, 0, 0, 1, 255, 0, 10, 7, 1, i)
    body += struct.pack(order + "B3i", 3, 0, 1, 0)
    return bytes([252]) + header.encode("ascii") + body


def main():
    seeds = {
        "reader-las-12-format0": las(2, 0),
        "reader-las-12-format1": las(2, 1),
        "reader-las-12-format3-vlr": las(2, 3, vlr=20),
        "reader-las-13-format2-extra": las(3, 2, extra=3),
        "reader-las-14-format6": las(4, 6),
        "reader-las-14-format8": las(4, 8, count=3),
        "reader-las-14-records": las_with_records(),
        "reader-ply-ascii": ply("ascii"),
        "reader-ply-binary-le": ply("binary_little_endian"),
        "reader-ply-binary-be-float": ply("binary_big_endian", "float"),
    }
    for name, data in seeds.items():
        with open(os.path.join(CORPUS, name), "wb") as handle:
            handle.write(data)
    print("wrote %d seeds to %s" % (len(seeds), CORPUS))


if __name__ == "__main__":
    main()
