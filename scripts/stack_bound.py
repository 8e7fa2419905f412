#!/usr/bin/env python3
"""The static stack bound of a function in a firmware ELF: the largest sum of stack frames
along any chain of calls from it, read from the machine code.

Usage: scripts/stack_bound.py ELF SYMBOL_PATTERN [--objdump PROGRAM] [--stop-at PATTERN]

For each function of the ELF (objdump's disassembly) the frame is what its code moves the
stack pointer down by: the registers of its `push`/`vpush`/`stmdb sp!` (Arm) or the
`addi sp, sp, -n` (RISC-V), plus every `sub sp` (an immediate, or a constant loaded from the
function's literal pool). Its callees are the targets of `bl`/`blx label` and of branches
that leave it (tail calls; counted as calls, an upper bound). The bound of a function is its
frame plus the largest bound of its callees; a call through a register (`blx rN`, `jalr`)
cannot be followed and is reported, so is recursion. Prints the bound of every function
whose demangled name matches the pattern, with its deepest chain. A function matching
`--stop-at` counts its own frame but not its callees': the panic machinery, say, whose stack
is the panic handler's, which ends the program.

Only the standard library of Python and binutils' objdump for the ELF's architecture.
"""
import re
import subprocess
import sys

FUNCTION = re.compile(r"^([0-9a-f]+) <(.*)>:$")
LINE = re.compile(r"^\s*([0-9a-f]+):\s+(\S+)\s*(.*)$")
WORD = re.compile(r"^\s*([0-9a-f]+):\s+(?:[0-9a-f]{8}\s+)?\.word\s+0x([0-9a-f]+)")
TARGET = re.compile(r"\b([0-9a-f]+) <([^>]+)>")


def registers(text):
    """The number of 32-bit registers in a register list such as {r4, r5, r6, r7, lr},
    {r4-r11, lr} or {d8-d15} (a d register is two words)."""
    inside = text[text.index("{") + 1 : text.index("}")]
    words = 0
    for part in inside.split(","):
        part = part.strip()
        size = 2 if part.startswith("d") else 1
        if "-" in part:
            lo, hi = part.split("-")
            words += size * (int(hi.strip()[1:]) - int(lo.strip()[1:]) + 1)
        else:
            words += size
    return 4 * words


def disassemble(elf, objdump):
    text = subprocess.run(
        [objdump, "-d", "-C", "--no-show-raw-insn", elf],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    functions = {}  # name -> dict(start, lines)
    words = {}
    current = None
    for line in text.splitlines():
        m = FUNCTION.match(line)
        if m:
            current = {"start": int(m.group(1), 16), "lines": []}
            functions[m.group(2)] = current
            continue
        w = WORD.match(line)
        if w:
            words[int(w.group(1), 16)] = int(w.group(2), 16)
            continue
        m = LINE.match(line)
        if m and current is not None:
            current["lines"].append((int(m.group(1), 16), m.group(2), m.group(3)))
    return functions, words


# Moves the stack pointer down by an immediate: Thumb's `sub sp, #n` and `sub.w sp, sp, #n`,
# RISC-V's `addi sp, sp, -n` (objdump may write it `add`) and `c.addi16sp sp, -n`.
SUB_SP = re.compile(r"^(sub|subw)$")
ADD_SP_NEGATIVE = re.compile(r"^sp,\s*(sp,\s*)?-(\d+)")
# A call or a branch that may leave the function: Arm's `b`, `bl`, `blx` and conditional
# branches, RISC-V's `j`, `jal`, `jalr`, `call`, `tail` and compressed forms. Only those naming
# a `<label>` are followed; an in-function target is left out below.
BRANCH = re.compile(r"^(b[a-z]*|j|jal|jalr|call|tail|c\.j|c\.jal|c\.jalr|c\.b[a-z]+)$")


def frame_and_calls(name, body, words, starts):
    """The bytes `body` moves the stack pointer down by, the functions it calls or branches
    to, and how many calls it makes through a register."""
    frame, calls, unknown = 0, set(), 0
    loaded = {}  # register -> constant loaded from the literal pool
    for _, op, args in body["lines"]:
        op = re.sub(r"\.[wn]$", "", op)  # Thumb-2's width suffixes
        code = args.split("@")[0].strip()  # without objdump's comment
        if op in ("push", "vpush") or (op == "stmdb" and code.startswith("sp!")):
            frame += registers(code)
        elif SUB_SP.match(op) and re.match(r"sp,\s*(sp,\s*)?#", code):
            frame += int(re.search(r"#(-?\d+)", code).group(1))
        elif op in ("add", "addi", "c.addi", "c.addi16sp") and ADD_SP_NEGATIVE.match(code):
            frame += int(ADD_SP_NEGATIVE.match(code).group(2))
        elif op == "add" and re.match(r"sp,\s*(sp,\s*)?r\d+$", code):
            # A large frame on the Cortex-M0: a negative constant from the literal pool.
            value = loaded.get(code.split(",")[-1].strip())
            if value is not None and value & 0x80000000:
                frame += (1 << 32) - value
        elif op == "ldr":
            m = re.match(r"(r\d+),\s*\[pc.*@\s*\(([0-9a-f]+)", args)
            if m and int(m.group(2), 16) in words:
                loaded[m.group(1)] = words[int(m.group(2), 16)]
        if BRANCH.match(op) and op not in ("bic", "bics", "bkpt", "bfi", "bfc"):
            t = TARGET.search(args)
            if t:
                target_name = re.sub(r"\+0x[0-9a-f]+$", "", t.group(2))
                if target_name != name and int(t.group(1), 16) in starts:
                    calls.add(starts[int(t.group(1), 16)])
            elif op in ("blx", "jalr", "c.jalr"):
                unknown += 1  # through a register: a function pointer or a trait object
    return frame, calls, unknown


def main():
    args = sys.argv[1:]
    objdump, stop = "arm-none-eabi-objdump", None
    if "--objdump" in args:
        i = args.index("--objdump")
        objdump = args[i + 1]
        del args[i : i + 2]
    if "--stop-at" in args:
        i = args.index("--stop-at")
        stop = re.compile(args[i + 1])
        del args[i : i + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    elf, pattern = args
    functions, words = disassemble(elf, objdump)
    starts = {body["start"]: name for name, body in functions.items()}
    info = {name: frame_and_calls(name, body, words, starts) for name, body in functions.items()}
    memo, onstack, recursive = {}, set(), set()

    def bound(name):
        if name in memo:
            return memo[name]
        if name in onstack:
            recursive.add(name)
            return (0, [name + " (recursion)"], 0)
        onstack.add(name)
        frame, calls, unknown = info.get(name, (0, set(), 0))
        if stop is not None and stop.search(name):
            calls, unknown = set(), 0
        best = (0, [], 0)
        total_unknown = unknown
        for callee in sorted(calls):  # ties resolved the same way every run
            b = bound(callee)
            total_unknown += b[2]
            if b[0] > best[0]:
                best = b
        onstack.discard(name)
        memo[name] = (frame + best[0], [f"{frame:6}  {name}"] + best[1], total_unknown)
        return memo[name]

    found = False
    for name in sorted(functions):
        if re.search(pattern, name):
            found = True
            total, chain, unknown = bound(name)
            print(f"{total} bytes: {name}")
            if unknown:
                print(f"  ({unknown} calls through a register below it, not followed)")
            for step in chain:
                print("  " + step)
    if recursive:
        print("recursion, not bounded:", ", ".join(sorted(recursive)))
    if not found:
        sys.exit(f"stack_bound.py: no function matches {pattern!r}")


if __name__ == "__main__":
    main()
