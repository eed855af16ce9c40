#!/usr/bin/env python3
"""Rewrite the cellsph payloads of a LAMMPS restart file, to test how the styles read versions.

  restart_version.py IN OUT newer STYLE        the STYLE payload claims the next format version
  restart_version.py IN OUT unversioned STYLE...  the STYLE payloads lose their version marker:
                                               the layout written before versions (version 1)

STYLE is cell/sph, cell/wall, cell/neohookean, cell/lamella or cell/turgor (unversioned: not
cell/sph, whose version 1 also lacks the per-pair wall flag, nor cell/lamella, which had versions
from its start). A payload is found by its style name as LAMMPS
writes it (int length, name, NUL) followed by the marker -version (src/*.cpp RESTART_VERSION):
an int for pair cell/sph, a double for pair cell/wall and bonds cell/neohookean and cell/lamella,
a double after the payload size for fix cell/turgor. Each style must be found exactly once; OUT is written only
then.
"""
import struct
import sys

# style: (bytes between the name and the marker, marker format)
LAYOUT = {"cell/sph": (0, "=i"), "cell/wall": (0, "=d"), "cell/neohookean": (0, "=d"),
          "cell/lamella": (0, "=d"),
          "cell/turgor": (4, "=d")}


def find_marker(data, style):
    """Offset and value of the style's version marker; exits unless found exactly once."""
    gap, fmt = LAYOUT[style]
    name = style.encode() + b"\0"
    key = struct.pack("=i", len(name)) + name
    hits = []
    start = data.find(key)
    while start >= 0:
        at = start + len(key) + gap
        (value,) = struct.unpack_from(fmt, data, at)
        if value < 0:
            hits.append((at, value))
        start = data.find(key, start + 1)
    if len(hits) != 1:
        sys.exit(f"restart_version.py: {len(hits)} versioned '{style}' payloads, expected 1")
    return hits[0]


def main():
    if len(sys.argv) < 5 or sys.argv[3] not in ("newer", "unversioned"):
        sys.exit(__doc__)
    src, dst, mode, styles = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    data = bytearray(open(src, "rb").read())
    for style in styles:
        if style not in LAYOUT or (mode == "unversioned" and style in ("cell/sph", "cell/lamella")):
            sys.exit(f"restart_version.py: cannot make '{style}' {mode}")
        gap, fmt = LAYOUT[style]
        at, marker = find_marker(data, style)
        version = int(round(-marker))
        if mode == "newer":
            struct.pack_into(fmt, data, at, type(marker)(-(version + 1)))
            print(f"restart_version.py: {style} payload version {version} -> {version + 1}")
        else:
            del data[at:at + struct.calcsize(fmt)]
            if gap:    # fix payload: its size precedes the marker
                (size,) = struct.unpack_from("=i", data, at - gap)
                struct.pack_into("=i", data, at - gap, size - struct.calcsize(fmt))
            print(f"restart_version.py: {style} payload version {version} -> unversioned")
    open(dst, "wb").write(data)


if __name__ == "__main__":
    main()
