#!/usr/bin/env bash
# The Raspberry Pi Pico program boards/rp2040-st7789 run in an emulator, end to end: built with
# its `single-core` feature (rp2040js, the emulator, has one core), run in rp2040js for one
# frame (scripts/pico/run.mjs records every byte on the display's SPI bus with the
# data/command and chip-select levels), the bytes read as the ST7789 would
# (scripts/pico/decode.mjs), and the picture compared, pixel for pixel, with the host's render
# of the same scene and camera (scripts/pico/host-render). Then the same with the program's
# `fault-byte-swap` feature, a deliberate fault in its DMA interface: that comparison must fail.
#
# Usage: scripts/pico.sh [--png FILE]
#
# It writes the streams, the pictures and the emulator's reports to
# boards/rp2040-st7789/target/pico/, and the emulated panel's picture as a PNG there
# (emulated.png), or to FILE with --png (the board README's picture:
# scripts/pico.sh --png boards/rp2040-st7789/emulated.png).
#
# What it needs: cargo with the thumbv6m-none-eabi target (added through rustup if missing),
# node and npm (installed from Debian's packages through apt-get if missing), and the npm
# registry for the pinned rp2040js (scripts/pico/package-lock.json, `npm ci`).
#
# Exit status: 0 if the picture matches and the fault is caught, 1 if not, 2 if something it
# needs is missing.
set -euo pipefail
export LC_ALL=C

root=$(cd "$(dirname "$0")/.." && pwd)
png=""
case ${1:-} in
    --png) png=${2:?usage: scripts/pico.sh [--png FILE]}; [[ $png == /* ]] || png="$PWD/$png" ;;
    "") ;;
    *) echo "usage: scripts/pico.sh [--png FILE]" >&2; exit 2 ;;
esac

target=thumbv6m-none-eabi
board="$root/boards/rp2040-st7789"
emulator="$root/scripts/pico"
out="$board/target/pico"
started=$SECONDS

# --- What it needs -------------------------------------------------------------------------

for command in cargo rustc timeout; do
    if ! command -v "$command" >/dev/null 2>&1; then
        echo "pico.sh: missing, and not installed by this script: $command" >&2
        exit 2
    fi
done
if [[ ! -d "$(rustc --print sysroot)/lib/rustlib/$target/lib" ]]; then
    if command -v rustup >/dev/null 2>&1; then
        rustup target add "$target"
    else
        echo "pico.sh: missing the Rust target $target, and no rustup to add it" >&2
        exit 2
    fi
fi
need=()
command -v node >/dev/null 2>&1 || need+=(nodejs)
command -v npm >/dev/null 2>&1 || need+=(npm)
if ((${#need[@]})); then
    if ! command -v apt-get >/dev/null 2>&1; then
        echo "pico.sh: missing ${need[*]}, and no apt-get to install them" >&2
        exit 2
    fi
    echo "pico.sh: installing ${need[*]} (Debian's packages)"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi
# The emulator, at the version package-lock.json pins.
(cd "$emulator" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)

mkdir -p "$out"
rm -f "$out"/*.bin "$out"/*.rgb565 "$out"/*.json "$out"/*.log "$out"/*.png "$out"/*.elf
[[ -n $png ]] || png="$out/emulated.png"

# --- The host's picture, and the programs ----------------------------------------------------

echo "pico.sh: the host's render"
(cd "$emulator/host-render" && cargo run --quiet --release --locked -- "$out/expected.rgb565")

# Both builds share the board's target directory (the dependencies are built once); each
# program is copied out before the next build replaces it.
elf="$board/target/$target/release/fixray-rp2040-st7789"
echo "pico.sh: the Pico program, single-core"
(cd "$board" && cargo build --quiet --release --locked --features single-core)
cp "$elf" "$out/program.elf"
echo "pico.sh: the Pico program, single-core, with the fault-byte-swap fault"
(cd "$board" && cargo build --quiet --release --locked --features single-core,fault-byte-swap)
cp "$elf" "$out/fault.elf"

# --- Run each in the emulator, decode, compare ------------------------------------------------

# emulate NAME: runs $out/NAME.elf in rp2040js; its report goes to $out/NAME.json, the bus to
# $out/NAME.bin. Fails unless the program ran past its frame: to its pause after the frame
# and its text, where run.mjs stops (or asleep after them).
emulate() {
    local name=$1
    if ! timeout 120 node "$emulator/run.mjs" "$out/$name.elf" "$out/$name.bin" \
        >"$out/$name.json" 2>"$out/$name.log"; then
        echo "pico.sh: the emulator failed on $name.elf (or took over two minutes):" >&2
        sed 's/^/    /' "$out/$name.log" "$out/$name.json" >&2
        exit 1
    fi
    if ! grep -Eq '"stopped":"(past the frame|asleep)"' "$out/$name.json"; then
        echo "pico.sh: $name.elf did not finish its frame in the emulator:" >&2
        sed 's/^/    /' "$out/$name.json" >&2
        head -n 20 "$out/$name.log" | sed 's/^/    /' >&2
        exit 1
    fi
    # rp2040js warns of registers it does not model; the program should touch none.
    if [[ -s $out/$name.log ]]; then
        echo "pico.sh: rp2040js warned while running $name.elf ($out/$name.log):"
        sort "$out/$name.log" | uniq -c | head -n 20 | sed 's/^/    /'
    fi
}

# field FILE KEY: a number from a report in $out.
field() {
    node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
             console.log(r[process.argv[2]]);' "$out/$1" "$2"
}

echo "pico.sh: running the program in rp2040js"
emulate program
status=0
node "$emulator/decode.mjs" "$out/program.bin" "$out/expected.rgb565" "$png" "$out/bands.json" ||
    status=$?
if ((status != 0)); then
    echo "pico.sh: the emulated panel's picture is not the host's (see above)" >&2
    exit 1
fi

frame=$(field program.json frameCycles)
rom=$(field program.json frameRomCycles)
total=$(field program.json cycles)
wall=$(field program.json wallSeconds)
if [[ $frame == null ]]; then
    echo "pico.sh: the program's two timer readings (the frame's start and end) were not found" >&2
    exit 1
fi
# The two-core program's frame, estimated from this run's bands (scripts/pico/estimate.mjs).
node "$emulator/estimate.mjs" "$out/program.json" "$out/bands.json" >"$out/estimate.json"
render=$(field estimate.json renderCycles)
send=$(field estimate.json sendCycles)
two=$(field estimate.json twoCores)
awk -v f="$frame" -v r="$rom" -v t="$total" -v w="$wall" -v render="$render" -v send="$send" \
    -v two="$two" 'BEGIN {
    ms = "%.1f ms at 133 MHz, %.1f ms at 125 MHz (the program'"'"'s clock)"
    printf "pico.sh: the frame, single core, measured: %d cycles, " ms "\n",
        f, f / 133e3, f / 125e3
    printf "pico.sh:   rendering %d cycles, sending %d (with the commands'"'"' wire time)\n",
        render, send
    printf "pico.sh:   %d cycles (%.2f%%) in the stand-in ROM routines\n", r, 100 * r / f
    printf "pico.sh: the frame, two cores, estimated from it: %d cycles, " ms "\n",
        two, two / 133e3, two / 125e3
    printf "pico.sh: %d cycles emulated in all (start-up delays included) in %.1f s\n", t, w
}'

echo "pico.sh: running the faulty program (fault-byte-swap) in rp2040js"
emulate fault
status=0
node "$emulator/decode.mjs" "$out/fault.bin" "$out/expected.rgb565" "$out/fault.png" || status=$?
case $status in
    1) echo "pico.sh: the fault is caught: the faulty program's picture differs, as it must" ;;
    0)
        echo "pico.sh: the faulty program's picture passed the comparison: the check is blind" >&2
        exit 1
        ;;
    *)
        echo "pico.sh: the faulty program's stream broke the decoder (status $status) rather" \
            "than drawing a wrong picture" >&2
        exit 1
        ;;
esac

echo "pico.sh: ok, in $((SECONDS - started)) s"
