#!/usr/bin/env python3
"""Where a firmware's frame spends its instructions, by function or by source line.

Reads QEMU's `-d in_asm,exec,nochain` log of a firmware run (from a file or a FIFO), counts
how often each guest instruction ran (each translated block's executions times its
instructions), maps the addresses to source through `addr2line -i` (inlined frames included),
keeps what ran inside `render_row`, and prints instructions per pixel by the innermost
function, or by a deeper chain of inlined callers with --depth, or by the function the
code was compiled into (outermost first) with --outer.

Usage: profile.py LOG ELF ADDR2LINE [--depth N] [--lines] [--outer [--calls]] [--top N] [--pixels N]
Normally run by scripts/profile.sh.
"""
import argparse
import collections
import re
import subprocess

parser = argparse.ArgumentParser()
parser.add_argument("log")
parser.add_argument("elf")
parser.add_argument("addr2line")
parser.add_argument("--depth", type=int, default=1, help="inlined callers to show")
parser.add_argument("--lines", action="store_true", help="group by source line too")
parser.add_argument("--outer", action="store_true",
                    help="group by the function the code was compiled into, not inlined ones")
parser.add_argument("--calls", action="store_true",
                    help="with --outer: also how often each function was entered, a pixel")
parser.add_argument("--top", type=int, default=40)
parser.add_argument("--pixels", type=int, default=160 * 128)
args = parser.parse_args()

# Each translated block is logged once when translated (IN: and its instructions), and each
# execution as a Trace line naming the block's host address; a host address can be reused by
# a later translation, so the latest translation before a Trace line is the one it ran.
blocks = {}
counts = collections.Counter()
trace = re.compile(rb"^Trace \d+: (0x[0-9a-f]+) ")
current, translating = [], False
with open(args.log, "rb") as log:
    for line in log:
        if line.startswith(b"Trace"):
            host = trace.match(line).group(1)
            if translating:
                blocks[host], translating = current, False
            for address in blocks.get(host, ()):
                counts[address] += 1
        elif line.startswith(b"IN:"):
            current, translating = [], True
        elif translating and line.startswith(b"0x"):
            current.append(int(line[2:10], 16))

addresses = sorted(counts)
out = subprocess.run(
    [args.addr2line, "-e", args.elf, "-f", "-i", "-C", "-a"] + ["%x" % a for a in addresses],
    capture_output=True, text=True, check=True).stdout.splitlines()
chains, address, i = {}, None, 0
while i < len(out):
    if out[i].startswith("0x"):
        address = int(out[i], 16)
        chains[address] = []
        i += 1
        continue
    place = out[i + 1] if i + 1 < len(out) else ""
    chains[address].append((out[i], place.rsplit("/", 1)[-1].split(" ")[0]))
    i += 2


def short(name):
    for _ in range(3):
        name = re.sub(r"<[^<>]*>", "", name)
    return name.replace("fixray::", "").replace("core::", "")


totals = collections.Counter()
entries = {}  # with --calls: each outermost function's first address, which a call enters
for address, count in counts.items():
    chain = chains.get(address, [])
    # fixray's code, inlined into the frame's render_row calls or called from them; the
    # firmware's own (and fixray's FrameHash, which the firmware calls) is left out. The
    # set-up's calls into fixray are in, at well under one instruction a pixel.
    names = [name for name, _ in chain]
    if not any("render_row" in n or ("fixray::" in n and "firmware" not in n) for n in names):
        continue
    if "firmware" in names[0] or any("FrameHash" in n for n in names):
        continue
    frames = chain[::-1][: args.depth] if args.outer else chain[: args.depth]
    parts = [short(name) + (":" + place.split(":")[-1] if args.lines else "")
             for name, place in frames]
    key = " < ".join(parts)
    totals[key] += count
    if args.calls and (key not in entries or address < entries[key]):
        entries[key] = address

total = sum(totals.values())
print("%.1f instructions a pixel in fixray's code (%d pixels)" % (total / args.pixels,
                                                                  args.pixels))
for key, count in totals.most_common(args.top):
    calls = ("  %6.2f calls" % (counts[entries[key]] / args.pixels)) if key in entries else ""
    print("%8.1f  %5.1f %%%s  %s" % (count / args.pixels, 100 * count / total, calls, key))
