#!/usr/bin/env python3
"""Rewrite the cellsph payloads of a LAMMPS restart file, to test how the styles read versions.

  restart_version.py IN OUT newer STYLE        the STYLE payload claims the next format version
  restart_version.py IN OUT unversioned STYLE...  the STYLE payloads lose their version marker:
                                               the layout written before versions (version 1)
  restart_version.py IN OUT older cell/turgor  the fix cell/turgor payload in the layout of
                                               version 2 (5 values per cell: no dry solids)
  restart_version.py IN OUT older cell/sph [12|11|5 [NAME=VALUE...]]
                                               the pair cell/sph payload of version 13 in the
                                               layout of version 12 (no wall boundary schedule),
                                               11 (default) or 5, with the
                                               settings of the keywords removed in version 12
                                               (NAME: eos, hmode, tref, shift, tensile, grow, lag,
                                               adhesion; default: off)
  restart_version.py IN OUT older cell/wall [smooth=0|1]
                                               the pair cell/wall payload of version 6 in the
                                               layout of version 5, every pair with an
                                               adhesion with the removed smooth flag (default 0)
  restart_version.py IN OUT older cell/bending the dihedral cell/bending payload of version 2 in
                                               the layout of version 1 (no form per type)

STYLE is cell/sph, cell/wall, cell/neohookean, cell/lamella, cell/turgor or cell/bending
(unversioned: not cell/sph, whose version 1 also lacks the per-pair wall flag, nor cell/lamella or
cell/bending, versioned from the start). A payload is found by its style name as LAMMPS
writes it (int length, name, NUL) followed by the marker -version (src/*.cpp RESTART_VERSION):
an int for pair cell/sph, a double for pair cell/wall, bonds cell/neohookean and cell/lamella and
dihedral cell/bending, a double after
the payload size for fix cell/turgor. Each style must be found exactly once; OUT is written only
then. A fix cell/turgor payload of version 8 (12 more global values: accel auto state, water
exchanged between cells, the waiting transfer, accel auto's wall edges; 20 values per cell: the
wall's water), 7 (12 more global values; 16 values per cell), 6 (9
more global values; 16 per cell), 5 (6 more global values; 16
per cell), 4 (5 more global values; 16 per cell) or 3 (6 per cell) loses what came after version 2
(the wall's water, the wall edges, the waiting transfer, the exchanged water, the accel auto state, the dry solids) when made
unversioned or older, so that it has the layout of versions 1 and 2 (5 per cell).
"""
import struct
import sys

# style: (bytes between the name and the marker, marker format)
LAYOUT = {"cell/sph": (0, "=i"), "cell/wall": (0, "=d"), "cell/neohookean": (0, "=d"),
          "cell/lamella": (0, "=d"),
          "cell/turgor": (4, "=d"), "cell/bending": (0, "=d")}


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


def turgor_to_version2(data, at, version):
    """Keep the version-2 values of the version-3 to -8 cell/turgor payload whose marker is at
    offset at: count, physical time, water moved [, accel, open and sealed samples, lag, its error
    (4-8)] [, water exchanged (5-8)] [, the waiting transfer's water and time, the step of its
    evaluation (6-8)] [, the wall edges (7, 8)], then per cell ID mass0 pi0 warned offset [solids
    (3-8), 10 accel auto sums (4-8) and 4 values of the wall's water (8)]."""
    (count,) = struct.unpack_from("=d", data, at + 8)
    n = int(count)
    extra, per = {8: (12, 20), 7: (12, 16), 6: (9, 16), 5: (6, 16), 4: (5, 16), 3: (0, 6)}[version]
    end = at + 8 * (4 + extra + per * n)
    values = list(struct.unpack_from(f"={per * n}d", data, at + 8 * (4 + extra)))
    kept = [v for k, v in enumerate(values) if k % per < 5]
    data[at + 8 * 4:end] = struct.pack(f"={5 * n}d", *kept)
    (size,) = struct.unpack_from("=i", data, at - 4)
    struct.pack_into("=i", data, at - 4, size - 8 * (extra + (per - 5) * n))
    struct.pack_into("=d", data, at, -2.0)


def header_count(data, total, count, name):
    """A type count from the restart header: the token total (a bigint: NATOMS 16, NDIHEDRALS 24)
    followed by the token count (an int: NTYPES 17, NDIHEDRALTYPES 25), as LAMMPS's write_restart
    writes them."""
    key = struct.pack("=i", total)
    start = data.find(key)
    while start >= 0:
        if struct.unpack_from("=i", data, start + 12)[0] == count:
            return struct.unpack_from("=i", data, start + 16)[0]
        start = data.find(key, start + 1)
    sys.exit(f"restart_version.py: no {name} in the restart header")


def bending_to_version1(data, at):
    """Drop the form column (n ints) of the version-2 dihedral cell/bending payload whose marker is
    at offset at: after the marker come n values each of G, t0 (doubles) and reference (int)."""
    n = header_count(data, 24, 25, "NDIHEDRALTYPES")
    start = at + 8 + 2 * 8 * n + 4 * n
    del data[start:start + 4 * n]
    struct.pack_into("=d", data, at, -1.0)


def sph_to_older(data, at, version, target, removed):
    """Write the version-13 pair cell/sph payload whose marker is at offset at in the layout of
    version target (12, 11 or 5), with the settings of the keywords removed in version 12 from removed
    (NAME=VALUE: eos 0 linear / 1 tait, hmode 0 / 1 mass / 2, tref, shift, tensile, grow, lag,
    adhesion; default: all off). Version 12, after the marker: kernel (int), cutoff (double), hmode
    (int), eta (double), temp flag (int), T (double), name length (int), name, background P_b
    (double), its name's length (int) and name, auto flag (int), P_min, P_b now (double), whether it
    is set (int), the wall boundary's schedule (last exact step: int64, interval, next interval:
    int, last jump: double); then per type pair I <= J setflag (int) and if set boundary (int),
    rho0, K, mu, h (double). Version 12 lacks the schedule. Version 11 has eos (int) after the kernel, Tref after T, shift, tensile eps (double),
    n (int), dp, grow (double) after the name, the lag (double) after P_min, and each set pair's
    adhesion W (double) after h; version 5 ends after shift (no background) with no W."""
    if version != 13:
        sys.exit(f"restart_version.py: cell/sph payload version {version}, expected 13")
    old = {"eos": 0, "hmode": None, "tref": 298.15, "shift": 0.0, "tensile": 0.0, "grow": 1.5,
           "lag": -1.0, "adhesion": 0.0}
    for item in removed:
        key, value = item.split("=")
        old[key] = float(value)
    kernel, cut, hmode, eta, tflag, temp, length = struct.unpack_from("=idididi", data, at + 4)
    pos = at + 4 + struct.calcsize("=idididi")
    name = bytes(data[pos:pos + length])
    pos += length
    (pb, blen) = struct.unpack_from("=di", data, pos)
    bname = bytes(data[pos + 12:pos + 12 + blen])
    pos += 12 + blen
    bauto, pmin, pbnow, bset = struct.unpack_from("=iddi", data, pos)
    pos += struct.calcsize("=iddi")
    schedule = struct.calcsize("=qiid")
    if target == 12:    # the current layout without the schedule
        del data[pos:pos + schedule]
        struct.pack_into("=i", data, at, -12)
        return
    pos += schedule
    hmode = int(old["hmode"]) if old["hmode"] is not None else hmode
    out = struct.pack("=iiididid", -target, kernel, int(old["eos"]), cut, hmode, eta, tflag, temp)
    out += struct.pack("=d", old["tref"]) + struct.pack("=i", length) + name
    out += struct.pack("=d", old["shift"])
    if target == 11:
        out += struct.pack("=didd", old["tensile"], 4, 0.0, old["grow"])
        out += struct.pack("=di", pb, blen) + bname + struct.pack("=idd", bauto, pmin, old["lag"])
        out += struct.pack("=di", pbnow, bset)
    n = header_count(data, 16, 17, "NTYPES")
    pairs = b""
    for _ in range(n * (n + 1) // 2):
        (setflag,) = struct.unpack_from("=i", data, pos)
        pairs += data[pos:pos + 4]
        pos += 4
        if setflag:
            pairs += data[pos:pos + 4 + 4 * 8]
            pos += 4 + 4 * 8
            if target == 11:
                pairs += struct.pack("=d", old["adhesion"])
    data[at:pos] = out + pairs


def wall_to_version5(data, at, version, smooth):
    """Write the version-6 pair cell/wall payload whose marker is at offset at in the layout of
    version 5, with the removed adhesion smooth flag (0 or 1) of every set type pair: after the
    marker the cutoff (double), then per type pair I <= J setflag (int) and if set the terms
    (int) and 14 doubles (f0 r0 p1 p2 D alpha ra rc eps sigma teps tsigma seps ssigma); version 5
    has the flag (double) after sigma."""
    if version != 6:
        sys.exit(f"restart_version.py: cell/wall payload version {version}, expected 6")
    n = header_count(data, 16, 17, "NTYPES")
    pos = at + 16
    for _ in range(n * (n + 1) // 2):
        (setflag,) = struct.unpack_from("=i", data, pos)
        pos += 4
        if setflag:
            (terms,) = struct.unpack_from("=i", data, pos)
            pos += 4 + 10 * 8
            data[pos:pos] = struct.pack("=d", smooth if terms & 2 else 0.0)    # 2: adhesion
            pos += 8 + 4 * 8
    struct.pack_into("=d", data, at, -5.0)


def main():
    if len(sys.argv) < 5 or sys.argv[3] not in ("newer", "unversioned", "older"):
        sys.exit(__doc__)
    src, dst, mode, styles = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    data = bytearray(open(src, "rb").read())
    for style in styles:
        if style not in LAYOUT or (mode == "unversioned" and style in ("cell/sph", "cell/lamella", "cell/bending")) or (
                mode == "older" and style not in ("cell/turgor", "cell/sph", "cell/wall", "cell/bending")):
            sys.exit(f"restart_version.py: cannot make '{style}' {mode}")
        gap, fmt = LAYOUT[style]
        at, marker = find_marker(data, style)
        version = int(round(-marker))
        if style == "cell/turgor" and mode != "newer" and version in (3, 4, 5, 6, 7, 8):
            turgor_to_version2(data, at, version)
        if style == "cell/sph" and mode == "older":
            target = int(styles[1]) if len(styles) > 1 else 11
            sph_to_older(data, at, version, target, styles[2:])
            print(f"restart_version.py: {style} payload version {version} -> {target}")
            break
        elif style == "cell/wall" and mode == "older":
            smooth = float(styles[1].split("=")[1]) if len(styles) > 1 else 0.0
            wall_to_version5(data, at, version, smooth)
            print(f"restart_version.py: {style} payload version {version} -> 5")
            break
        elif style == "cell/bending" and mode == "older":
            if version != 2:
                sys.exit(f"restart_version.py: cell/bending payload version {version}, expected 2")
            bending_to_version1(data, at)
            print(f"restart_version.py: {style} payload version {version} -> 1")
        elif mode == "older":
            print(f"restart_version.py: {style} payload version {version} -> 2")
        elif mode == "newer":
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
