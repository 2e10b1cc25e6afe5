"""A minimal DNG writer for the tests: a little-endian TIFF with one uncompressed 16-bit CFA
image and the few DNG tags a raw reader needs (DNGVersion, CFA pattern, black and white levels).
No imaging library: the tests know every sample they write."""

import struct

# CFA colour codes of TIFF/EP: 0 red, 1 green, 2 blue.
_CODES = {"R": 0, "G": 1, "B": 2}


def write_dng(path, cfa_rows, *, pattern="RGGB", black=0, white=65535, model="gmcc test camera",
              black_per_channel=None, extra_tags=()):
    """`cfa_rows`: rows of integers 0..65535, the sensor's samples (even width and height);
    `pattern`: the 2×2 Bayer pattern read row by row (RGGB, BGGR, GRBG or GBRG);
    `black`: BlackLevel (one value), or `black_per_channel` four values in pattern order
    (BlackLevelRepeatDim 2×2); `white`: WhiteLevel."""
    h, w = len(cfa_rows), len(cfa_rows[0])
    data = b"".join(struct.pack("<%dH" % w, *row) for row in cfa_rows)
    model_bytes = model.encode() + b"\0"
    tags = []  # (tag, type, count, value bytes)

    def tag(code, kind, values):
        fmt = {1: "B", 2: "s", 3: "H", 4: "I", 5: "II", 10: "ii"}[kind]
        if kind == 2:
            body = values
            count = len(values)
        elif kind in (5, 10):
            body = b"".join(struct.pack("<" + fmt, *v) for v in values)
            count = len(values)
        else:
            body = struct.pack("<%d%s" % (len(values), fmt), *values)
            count = len(values)
        tags.append((code, kind, count, body))

    tag(254, 4, [0])                      # NewSubfileType: the main image
    tag(256, 4, [w])                      # ImageWidth
    tag(257, 4, [h])                      # ImageLength
    tag(258, 3, [16])                     # BitsPerSample
    tag(259, 3, [1])                      # Compression: none
    tag(262, 3, [32803])                  # PhotometricInterpretation: CFA
    tag(271, 2, b"gmcc\0")                # Make
    tag(272, 2, model_bytes)              # Model
    tag(273, 4, [0])                      # StripOffsets (patched below)
    tag(274, 3, [1])                      # Orientation
    tag(277, 3, [1])                      # SamplesPerPixel
    tag(278, 4, [h])                      # RowsPerStrip
    tag(279, 4, [len(data)])              # StripByteCounts
    tag(284, 3, [1])                      # PlanarConfiguration
    tag(33421, 3, [2, 2])                 # CFARepeatPatternDim
    tag(33422, 1, [_CODES[c] for c in pattern])  # CFAPattern
    tag(50706, 1, [1, 4, 0, 0])           # DNGVersion
    tag(50708, 2, model_bytes)            # UniqueCameraModel
    if black_per_channel is not None:
        tag(50713, 3, [2, 2])             # BlackLevelRepeatDim
        tag(50714, 4, list(black_per_channel))
    else:
        tag(50714, 4, [black])            # BlackLevel
    tag(50717, 4, [white])                # WhiteLevel
    tag(50721, 10, [(1, 1), (0, 1), (0, 1), (0, 1), (1, 1), (0, 1), (0, 1), (0, 1), (1, 1)])  # ColorMatrix1
    tag(50778, 3, [21])                   # CalibrationIlluminant1: D65
    for t in extra_tags:
        tag(*t)
    tags.sort(key=lambda t: t[0])

    ifd_offset = 8
    ifd_size = 2 + 12 * len(tags) + 4
    extra_offset = ifd_offset + ifd_size
    extra = bytearray()
    entries = []
    for code, kind, count, body in tags:
        if len(body) <= 4:
            entries.append((code, kind, count, body.ljust(4, b"\0"), None))
        else:
            entries.append((code, kind, count, None, extra_offset + len(extra)))
            extra += body
            if len(extra) % 2:
                extra += b"\0"
    data_offset = extra_offset + len(extra)
    out = bytearray(b"II*\0" + struct.pack("<I", ifd_offset) + struct.pack("<H", len(tags)))
    for code, kind, count, inline, offset in entries:
        if code == 273:
            inline = struct.pack("<I", data_offset)
        out += struct.pack("<HHI", code, kind, count) + (inline if inline is not None else struct.pack("<I", offset))
    out += struct.pack("<I", 0) + extra + data
    with open(path, "wb") as f:
        f.write(bytes(out))
