"""Writes the LAS test files of tests/formats/LasTest.cpp.

No program that writes LAS is packaged in Debian bookworm (no PDAL, laspy, libLAS or LAStools;
its CloudCompare is built without LAS support), so these files are written here with struct,
field by field from the ASPRS LAS specifications 1.2, 1.3 R11 and 1.4 R13. They are NOT the
output of a real writer: the test checks the reader against the values listed below, which
this script put in (known integers, scales and offsets far from zero).

Files: las<version>_f<format>.las for LAS 1.2 (formats 0-3), 1.3 (4, 5) and 1.4 (6-10, and 1 as
a legacy format in a 1.4 file); las14_f7_extra.las, whose records carry 4 extra bytes (described
by an Extra Bytes VLR); las14_f6_evlr.las, with an extended VLR after the points.
"""

import struct
import sys

# The points, the same in every file (LasTest.cpp holds the same lists).
X = [0, 1, -1, 123456, -654321, 999999]
Y = [0, 2, -2, 234567, -765432, 888888]
Z = [0, 3, -3, 34567, -76543, 77777]
SCALE = (0.001, 0.001, 0.01)
OFFSET = (500000.0, 4000000.0, 100.0)
INTENSITY = [0, 1, 65535, 1234, 40000, 7]
SCAN_DIRECTION = [0, 1, 0, 1, 1, 0]
EDGE = [1, 0, 0, 1, 0, 1]
USER_DATA = [0, 1, 127, 128, 200, 255]
POINT_SOURCE = [0, 1, 65535, 1234, 2, 3]
GPS_TIME = [300000000.0 + t for t in (0.0, 0.5, 1.25, 10.125, 100.0625, 3600.5)]
RED = [0, 1, 65535, 256, 1000, 30000]
GREEN = [65535, 2, 0, 512, 2000, 40000]
BLUE = [7, 3, 1, 1024, 3000, 50000]
NIR = [9, 4, 65535, 2048, 4000, 60000]
# Formats 0-5: 3-bit returns, 5-bit class, 3 flags (synthetic 1, key-point 2, withheld 4), scan
# angle rank in whole degrees.
LEGACY_RETURN = [1, 2, 3, 4, 5, 7]
LEGACY_RETURNS = [1, 2, 3, 5, 7, 7]
LEGACY_CLASS = [0, 1, 2, 6, 9, 31]
LEGACY_FLAGS = [0, 1, 2, 4, 7, 3]
LEGACY_ANGLE = [-90, -1, 0, 1, 45, 90]
# Formats 6-10: 4-bit returns, 8-bit class, 4 flags (+ overlap 8), scanner channel, scan angle in
# units of 0.006 degrees.
RETURN = [1, 2, 3, 8, 15, 15]
RETURNS = [1, 2, 4, 9, 15, 15]
CLASS = [0, 1, 2, 6, 64, 255]
FLAGS = [0, 1, 2, 4, 8, 15]
CHANNEL = [0, 1, 2, 3, 0, 3]
ANGLE = [-15000, -1, 0, 1, 7500, 15000]

FORMAT_SIZE = {0: 20, 1: 28, 2: 26, 3: 34, 4: 57, 5: 63, 6: 30, 7: 36, 8: 38, 9: 59, 10: 67}
HEADER_SIZE = {2: 227, 3: 235, 4: 375}


def legacy_core(i):
    bits = LEGACY_RETURN[i] | LEGACY_RETURNS[i] << 3 | SCAN_DIRECTION[i] << 6 | EDGE[i] << 7
    classification = LEGACY_CLASS[i] | LEGACY_FLAGS[i] << 5
    return struct.pack('<iiiHBBbBH', X[i], Y[i], Z[i], INTENSITY[i], bits, classification,
                       LEGACY_ANGLE[i], USER_DATA[i], POINT_SOURCE[i])


def extended_core(i):
    returns = RETURN[i] | RETURNS[i] << 4
    flags = FLAGS[i] | CHANNEL[i] << 4 | SCAN_DIRECTION[i] << 6 | EDGE[i] << 7
    return struct.pack('<iiiHBBBBhHd', X[i], Y[i], Z[i], INTENSITY[i], returns, flags, CLASS[i],
                       USER_DATA[i], ANGLE[i], POINT_SOURCE[i], GPS_TIME[i])


def wave_packet(i):
    # descriptor index, byte offset to the waveform data, its size, the return point's location
    # and the x(t), y(t), z(t) vector: written, not read.
    return struct.pack('<BQIffff', 1, 1000 * i, 256, 12.5 * i, 0.25, -0.5, 1.0)


def record(point_format, i):
    rgb = struct.pack('<HHH', RED[i], GREEN[i], BLUE[i])
    gps = struct.pack('<d', GPS_TIME[i])
    if point_format < 6:
        data = legacy_core(i)
        if point_format in (1, 3, 4, 5):
            data += gps
        if point_format in (2, 3, 5):
            data += rgb
        if point_format in (4, 5):
            data += wave_packet(i)
    else:
        data = extended_core(i)
        if point_format in (7, 8, 10):
            data += rgb
        if point_format in (8, 10):
            data += struct.pack('<H', NIR[i])
        if point_format in (9, 10):
            data += wave_packet(i)
    assert len(data) == FORMAT_SIZE[point_format], (point_format, len(data))
    return data


def vlr(user, record_id, payload, description, extended=False):
    length = struct.pack('<Q', len(payload)) if extended else struct.pack('<H', len(payload))
    return (struct.pack('<H16sH', 0, user.encode(), record_id) + length +
            struct.pack('<32s', description.encode()) + payload)


def bounds():
    values = []
    for axis, ints in enumerate((X, Y, Z)):
        coords = [v * SCALE[axis] + OFFSET[axis] for v in ints]
        values += [max(coords), min(coords)]
    return values


def header(minor, point_format, record_length, points, offset_to_points, vlrs, evlr_start=0,
           evlrs=0):
    size = HEADER_SIZE[minor]
    legacy = points if point_format < 6 else 0
    by_return = [0] * 15
    returns = LEGACY_RETURN if point_format < 6 else RETURN
    for r in returns[:points]:
        by_return[r - 1] += 1
    legacy_by_return = by_return[:5] if point_format < 6 else [0] * 5
    # Global encoding bit 0: GPS times are adjusted standard GPS time; bit 4 (1.4): the CRS is WKT.
    encoding = 1 | (16 if minor == 4 else 0)
    data = struct.pack('<4sHH16sBB32s32sHHHIIBHI5I', b'LASF', 0, encoding, bytes(16), 1, minor,
                       b'osgGlyphs test data', b'write_las.py from the LAS spec', 1, 2024, size,
                       offset_to_points, vlrs, point_format, record_length, legacy,
                       *legacy_by_return)
    data += struct.pack('<3d3d6d', *SCALE, *OFFSET, *bounds())
    if minor >= 3:
        data += struct.pack('<Q', 0)  # start of the waveform data packet record: none inside
    if minor >= 4:
        data += struct.pack('<QIQ15Q', evlr_start, evlrs, points, *by_return)
    assert len(data) == size
    return data


def write(path, minor, point_format, extra=b'', extended_vlr=False):
    records = b''.join(record(point_format, i) + extra for i in range(len(X)))
    record_length = FORMAT_SIZE[point_format] + len(extra)
    vlrs = [vlr('osgGlyphs', 1, b'a VLR the reader skips', 'test')]
    if extra:
        # An Extra Bytes VLR (LASF_Spec 4): one 192-byte descriptor of an unsigned long.
        descriptor = struct.pack('<2sBB32s4s', bytes(2), 6, 0, b'extra', bytes(4)) + bytes(192 - 40)
        vlrs.append(vlr('LASF_Spec', 4, descriptor, 'Extra Bytes'))
    vlr_bytes = b''.join(vlrs)
    offset = HEADER_SIZE[minor] + len(vlr_bytes)
    evlr = vlr('osgGlyphs', 2, b'an extended VLR after the points', 'test', True) if extended_vlr else b''
    evlr_start = offset + len(records) if evlr else 0
    data = header(minor, point_format, record_length, len(X), offset, len(vlrs), evlr_start,
                  1 if evlr else 0)
    with open(path, 'wb') as out:
        out.write(data + vlr_bytes + records + evlr)


def main(folder):
    for point_format in range(4):
        write(f'{folder}/las12_f{point_format}.las', 2, point_format)
    for point_format in (4, 5):
        write(f'{folder}/las13_f{point_format}.las', 3, point_format)
    for point_format in (1, 6, 7, 8, 9, 10):
        write(f'{folder}/las14_f{point_format}.las', 4, point_format)
    write(f'{folder}/las14_f7_extra.las', 4, 7, extra=struct.pack('<I', 0xDEADBEEF))
    write(f'{folder}/las14_f6_evlr.las', 4, 6, extended_vlr=True)


if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else '.')
