#!/usr/bin/env bash
# Renders fixray's demo and classic scenes (160 × 128) on three microcontrollers under QEMU,
# checks every frame's hash against the host's render, and prints one row per target,
# renderer and scene:
#
#   target, renderer (with the scene: `fixed`, `fixed-classic`, `reference-f32`, ...),
#   hash (match / MISMATCH), instructions per frame and per pixel, flash bytes, RAM bytes
#   (static RAM + peak stack, also shown apart).
#
# Each row is one of the firmware's binaries, which renders one scene with one renderer:
# `fixed` (Q16.16), `reference` (the f64 reference model) or `reference_f32` (the same model in
# f32), on the demo scene or the classic one (`_classic`), the latter also without shadow rays
# (`_noshadow`) and without mirrors (`_nomirror`) to show what each costs.
#
# Usage: scripts/firmware.sh
#
# It installs nothing. It needs cargo with the targets thumbv6m-none-eabi,
# thumbv7em-none-eabihf and riscv32imc-unknown-none-elf, qemu-system-arm (machines microbit
# and mps2-an386), qemu-system-riscv32 (machine virt) and timeout, and says which are missing.
# The QEMU command lines (-icount shift=0, semihosting, a `timeout`) are the runners in
# firmware/.cargo/config.toml, so `cargo run --release --target T --bin B` inside firmware/
# runs one firmware exactly as this script does. Each run's full output is kept in
# firmware/target/firmware-logs/.
#
# Exit status: 0 if every firmware ran and every hash matched, 1 otherwise, 2 if something
# it needs is missing.

set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
firmware="$root/firmware"
targets=(thumbv6m-none-eabi thumbv7em-none-eabihf riscv32imc-unknown-none-elf)
bins=(fixed fixed_noshadow fixed_shoot fixed_rays
    fixed_classic fixed_classic_noshadow fixed_classic_nomirror
    reference reference_classic reference_f32 reference_f32_classic)

# --- What it needs -------------------------------------------------------------------------

missing=()
need_command() { # command, how to get it
    command -v "$1" >/dev/null 2>&1 || missing+=("$1: $2")
}
need_command cargo "install Rust with rustup"
need_command rustc "install Rust with rustup"
need_command timeout "install coreutils"
need_command qemu-system-arm "apt-get install qemu-system-arm"
need_command qemu-system-riscv32 "apt-get install qemu-system-misc"
if command -v rustc >/dev/null 2>&1; then
    sysroot=$(rustc --print sysroot)
    for target in "${targets[@]}"; do
        [[ -d "$sysroot/lib/rustlib/$target/lib" ]] ||
            missing+=("the Rust target $target: rustup target add $target")
    done
fi
if command -v qemu-system-arm >/dev/null 2>&1; then
    machines=$(qemu-system-arm -machine help)
    for machine in microbit mps2-an386; do
        grep -qw -- "$machine" <<<"$machines" ||
            missing+=("QEMU machine $machine: a qemu-system-arm that has it (QEMU 7 or later)")
    done
fi
if ((${#missing[@]})); then
    echo "firmware.sh: missing, and not installed by this script:" >&2
    printf '  - %s\n' "${missing[@]}" >&2
    exit 2
fi

# --- The host's hashes ---------------------------------------------------------------------

# Lines of `renderer hash`, e.g. `fixed-classic 0x1234abcd`, for every renderer and scene. The
# dev profile reuses what `cargo test` built; the hashes are the same in any profile.
host=$(cd "$root" && cargo run --quiet --example frame_hash)
declare -A host_hash
while read -r renderer hash; do
    host_hash[$renderer]=$hash
done <<<"$host"

# --- Build, run, compare -------------------------------------------------------------------

for target in "${targets[@]}"; do
    (cd "$firmware" && cargo build --quiet --release --target "$target" --bins)
done

logs="$firmware/target/firmware-logs"
mkdir -p "$logs"

field() { # key, text: the value of the first `key=value` in text
    sed -n "s/.*\<$1=\([^ ]*\).*/\1/p" <<<"$2" | head -n 1
}
line() { # prefix: the line of the current run's report that starts with it
    grep "^$1" "$log" || true
}

failed=0
calibrations=()
names=()
row() { printf '%-28s %-24s %-8s %12s %9s %7s %7s %7s %7s\n' "$@"; }
row target renderer hash instr/frame instr/px flash ram static stack
for target in "${targets[@]}"; do
    for bin in "${bins[@]}"; do
        log="$logs/$target-$bin.txt"
        status=0
        (cd "$firmware" && cargo run --quiet --release --target "$target" --bin "$bin") \
            >"$log" 2>&1 || status=$?
        renderer=$(field renderer "$(line board=)")
        frame=$(line frame:)
        memory=$(line memory:)
        hash=$(field hash "$frame")
        if ((status != 0)) || [[ -z $hash || -z $memory ]]; then
            row "$target" "${renderer:-$bin}" "FAILED" "exit $status" - - - - -
            sed 's/^/    /' "$log" | tail -n 5 >&2
            failed=1
            continue
        fi
        [[ " ${names[*]} " == *" $renderer "* ]] || names+=("$renderer")
        verdict=MISMATCH
        [[ $hash == "${host_hash[$renderer]:-none}" ]] && verdict=match
        [[ $verdict == match ]] || failed=1
        static=$(field static_ram "$memory")
        stack=$(field peak_stack "$memory")
        row "$target" "$renderer" "$verdict" "$(field instructions "$frame")" \
            "$(field per_pixel "$frame")" "$(field flash "$memory")" $((static + stack)) \
            "$static" "$stack"
        if [[ $bin == "${bins[0]}" ]]; then # the counter is the same for every renderer
            counter=$(line counter: | sed 's/^counter: //; s/ instructions_per_tick=.*//')
            per_tick=$(field instructions_per_tick "$(line counter:)")
            calibration=$(line calibration:)
            calibrations+=("$target: $counter, $per_tick instructions per tick;
      a loop of $(field expected "$calibration") counted as $(field measured "$calibration")")
        fi
    done
done

echo
echo "host hashes (examples/frame_hash.rs):"
for renderer in "${names[@]}"; do
    printf '  %-24s %s\n' "$renderer" "${host_hash[$renderer]:-none}"
done
echo "instruction counters (QEMU -icount shift=0), each checked by a loop of known length:"
printf '  %s\n' "${calibrations[@]}"
echo "ram = static RAM + peak stack, in bytes; instructions count the render_row calls only."
echo "built with $(rustc --version), run on $(qemu-system-arm --version | head -n 1)"
echo "firmware.sh: $( ((failed)) && echo FAILED || echo ok ) in ${SECONDS} s"
exit "$failed"
