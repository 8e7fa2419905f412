#!/usr/bin/env python3
"""Bytes of code and read-only data that fixray itself puts in a firmware ELF.

Usage: scripts/own_code.py ELF

Sums the sizes of the ELF's function and object symbols whose mangled names are fixray's own
paths (`fixray::...`, legacy or v0 mangling): its functions, the monomorphised copies of its
generic ones, and its tables. Code of fixray's that the compiler inlined into a caller outside
the crate (the firmware's harness) is counted there, not here. Only the standard library of
Python: the ELF's section headers, symbol table and string table, 32- or 64-bit, little-endian.
"""
import re
import struct
import sys

# `_ZN6fixray...` (legacy), `_ZN..._$LT$fixray..` (a legacy trait impl on one of fixray's
# types) or `_R...6fixray...` (v0, the crate's name with its length), not `fixray_reference`
# or `fixray_firmware`.
OWN = re.compile(rb"^(_ZN6fixray|_ZN\d+_\$LT\$fixray\.\.|_R[A-Za-z0-9_]*?6fixray(?![_A-Za-z0-9]))")


def own_bytes(data):
    if data[:4] != b"\x7fELF" or data[5] != 1:
        sys.exit("own_code.py: not a little-endian ELF")
    wide = data[4] == 2
    if wide:
        shoff, = struct.unpack_from("<Q", data, 0x28)
        shentsize, shnum = struct.unpack_from("<HH", data, 0x3A)
    else:
        shoff, = struct.unpack_from("<I", data, 0x20)
        shentsize, shnum = struct.unpack_from("<HH", data, 0x2E)
    sections = []
    for i in range(shnum):
        base = shoff + i * shentsize
        if wide:
            _, kind, _, _, offset, size, link, _, _, entsize = struct.unpack_from("<IIQQQQIIQQ", data, base)
        else:
            _, kind, _, _, offset, size, link, _, _, entsize = struct.unpack_from("<IIIIIIIIII", data, base)
        sections.append((kind, offset, size, link, entsize))
    total = 0
    for kind, offset, size, link, entsize in sections:
        if kind != 2:  # SHT_SYMTAB
            continue
        strtab = sections[link]
        for at in range(offset, offset + size, entsize):
            if wide:
                name, info, _, shndx, _, sym_size = struct.unpack_from("<IBBHQQ", data, at)
            else:
                name, _, sym_size, info, _, shndx = struct.unpack_from("<IIIBBH", data, at)
            if shndx == 0 or (info & 0xF) not in (1, 2):  # defined STT_OBJECT or STT_FUNC
                continue
            start = strtab[1] + name
            end = data.index(b"\0", start)
            if OWN.match(data[start:end]):
                total += sym_size
    return total


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: scripts/own_code.py ELF")
    with open(sys.argv[1], "rb") as f:
        print(own_bytes(f.read()))
