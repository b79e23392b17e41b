"""
MODULE:    testsuite/stacks_fixture.py (r3.sbrt addon)
PURPOSE:   An SBRT's stacks file as the tests handle it: where it lies,
           a copy, and the same stacks as format 2.0 wrote them (the 2.1
           block summaries cut out)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import struct
import zlib

import grass.script as gs

# offsets in the format 2 header (lib/sbrt/format/format_v2.hpp)
AT_MINOR, AT_HEADER_SIZE, AT_OPTIONAL = 10, 12, 20
AT_TABLE, AT_END = 124, 132
OPTIONAL_SUMMARY = 1 << 1


def sbrt_dir(name):
    env = gs.gisenv()
    return os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "sbrt", name)


def stacks_path(name):
    return os.path.join(sbrt_dir(name), "stacks")


def copy_sbrt(source, target):
    shutil.rmtree(sbrt_dir(target), ignore_errors=True)
    shutil.copytree(sbrt_dir(source), sbrt_dir(target))


def summary_section(data):
    """[begin, end) of the 2.1 summary section: it ends at the block table,
    its last 8 bytes give its size."""
    table = struct.unpack_from("<Q", data, AT_TABLE)[0]
    size = struct.unpack_from("<Q", data, table - 8)[0]
    return table - size, table


def reseal_header(data):
    header_size = struct.unpack_from("<I", data, AT_HEADER_SIZE)[0]
    struct.pack_into("<I", data, header_size - 4, zlib.crc32(bytes(data[: header_size - 4])))


def as_format_20(name):
    """The stacks of SBRT `name` as the 2.0 writer wrote them: the summary
    section cut out, the table and end moved, minor 0, the bit cleared."""
    with open(stacks_path(name), "rb") as f:
        data = bytearray(f.read())
    begin, end = summary_section(data)
    data = data[:begin] + data[end:]
    cut = end - begin
    for at in (AT_TABLE, AT_END):
        struct.pack_into("<Q", data, at, struct.unpack_from("<Q", data, at)[0] - cut)
    struct.pack_into("<H", data, AT_MINOR, 0)
    optional = struct.unpack_from("<I", data, AT_OPTIONAL)[0]
    struct.pack_into("<I", data, AT_OPTIONAL, optional & ~OPTIONAL_SUMMARY)
    reseal_header(data)
    with open(stacks_path(name), "wb") as f:
        f.write(data)
