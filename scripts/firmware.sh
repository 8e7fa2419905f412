#!/usr/bin/env bash
# Renders fixray's demo and classic scenes (160 × 128) on four microcontrollers under QEMU,
# checks every frame's hash against the host's render, and prints one row per target,
# renderer and scene:
#
#   target, renderer (with the scene: `fixed`, `fixed-classic`, `reference-f32`, ...),
#   hash (match / MISMATCH), instructions per frame and per pixel, flash bytes, the bytes of
#   fixray's own code and data in it (scripts/own_code.py), RAM bytes
#   (static RAM + peak stack, also shown apart).
#
# Each row is one of the firmware's binaries, which renders one scene with one renderer:
# `fixed` (Q16.16), `reference` (the f64 reference model) or `reference_f32` (the same model in
# f32), on the demo scene or the classic one (`_classic`), the latter also without shadow rays
# (`_noshadow`), without mirrors (`_nomirror`) and with its glass opaque (`_opaque`) to show what
# each costs.
#
# Then `animate`: the demo scene with a ball rolling across its floor, each frame redrawn only
# where fixray's `Damage` says it can have changed and then in full, with the instructions of
# each, and the hashes of what it drew checked against the host's; and `progressive`: the
# demo scene in progressive passes, each pass's instructions against the full frame's.
#
# Usage: scripts/firmware.sh [--markdown]
#
# The chips, their QEMU machines and their names in tables are firmware/targets.tsv's lines;
# the script checks that firmware/.cargo/config.toml's runners boot each target on its machine.
# It installs nothing. It needs cargo with those Rust targets, their QEMU system emulators
# and machines, timeout and flock, and says which are missing. The QEMU command lines
# (-icount shift=0, semihosting, a `timeout`) are the runners in firmware/.cargo/config.toml,
# so `cargo run --release --target T --bin B` inside firmware/ runs one firmware as this
# script does (the same pictures and much the same figures; the script's own build, below,
# makes the figures independent of where the checkout lies). Each run's full output is kept
# in firmware/target/firmware-logs/.
#
# Every run also writes the README's performance tables (instructions per pixel; flash and
# RAM), as Markdown from this run's figures, to firmware/target/firmware-tables.md, which
# scripts/check-readme-tables.sh compares with the README. With --markdown the tables are
# printed on standard output too, and the report goes to standard error:
#
#   scripts/firmware.sh --markdown > tables.md
#
# Last, `codegen_check` on each chip: probes of compiler miscompiles known to have changed a
# frame (firmware/src/codegen.rs), each with the answer rustc's constant evaluator gives. A
# wrong answer means the toolchain miscompiles that pattern on that chip, so a frame that
# differs there may be the compiler's doing, not the renderer's.
#
# A probe answered wrong is reported, not failed: the frames' hashes are what must match, and
# the probe says whether the toolchain still carries a bug fixray's frames have met.
#
# Exit status: 0 if every firmware ran and every hash matched, 1 otherwise, 2 if something it
# needs is missing or the target table and config.toml disagree.

set -euo pipefail
export LC_ALL=C # decimal points and sorting the same everywhere

markdown=0
case ${1:-} in
    --markdown) markdown=1; exec 3>&1 1>&2 ;; # the tables on stdout, the report on stderr
    "") ;;
    *) echo "usage: scripts/firmware.sh [--markdown]" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "$0")/.." && pwd)
firmware="$root/firmware"

# --- The chips: firmware/targets.tsv -------------------------------------------------------

targets=()
declare -A qemu_of machine_of options_of chip_of board_of
while IFS=$'\t' read -r target qemu machine options chip board; do
    [[ -z $target || $target == \#* ]] && continue
    targets+=("$target")
    qemu_of[$target]=$qemu machine_of[$target]=$machine chip_of[$target]=$chip
    [[ $options == - ]] && options=""
    board_of[$target]=$board options_of[$target]=$options
done <"$firmware/targets.tsv"

# The runners in config.toml must boot each target on the table's machine, and run no other.
config="$firmware/.cargo/config.toml"
disagree=()
mapfile -t configured < <(sed -n 's/^\[target\.\(.*\)\]$/\1/p' "$config")
[[ "${configured[*]}" == "${targets[*]}" ]] ||
    disagree+=("config.toml has runners for (${configured[*]}), the table lists (${targets[*]})")
for target in "${targets[@]}"; do
    # The target's section, its lines joined, e.g. `... "qemu-system-arm", "-machine", "microbit", ...`.
    section=$(awk -v head="[target.$target]" '$0 == head {on = 1; next} /^\[/ {on = 0} on' \
        "$config" | tr '\n' ' ' | tr -s ' ')
    want="\"${qemu_of[$target]}\", \"-machine\", \"${machine_of[$target]}\""
    for option in ${options_of[$target]}; do
        want+=", \"$option\""
    done
    [[ $section == *"$want"* ]] ||
        disagree+=("config.toml's runner for $target does not start QEMU as $want")
done
if ((${#disagree[@]})); then
    echo "firmware.sh: firmware/targets.tsv and firmware/.cargo/config.toml disagree:" >&2
    printf '  - %s\n' "${disagree[@]}" >&2
    exit 2
fi
bins=(fixed fixed_noshadow fixed_shoot fixed_rays
    fixed_classic fixed_classic_noshadow fixed_classic_nomirror fixed_classic_opaque
    reference reference_classic reference_f32 reference_f32_classic)

# --- What it needs -------------------------------------------------------------------------

missing=()
need_command() { # command, how to get it
    command -v "$1" >/dev/null 2>&1 || missing+=("$1: $2")
}
need_command cargo "install Rust with rustup"
need_command rustc "install Rust with rustup"
need_command timeout "install coreutils"
need_command flock "install util-linux"
need_command python3 "apt-get install python3"
need_command arm-none-eabi-objdump "apt-get install binutils-arm-none-eabi"
need_command riscv64-unknown-elf-objdump "apt-get install binutils-riscv64-unknown-elf"
for qemu in $(printf '%s\n' "${qemu_of[@]}" | sort -u); do
    case $qemu in
        qemu-system-arm) need_command "$qemu" "apt-get install qemu-system-arm" ;;
        *) need_command "$qemu" "apt-get install qemu-system-misc" ;;
    esac
done
if command -v rustc >/dev/null 2>&1; then
    sysroot=$(rustc --print sysroot)
    for target in "${targets[@]}"; do
        [[ -d "$sysroot/lib/rustlib/$target/lib" ]] ||
            missing+=("the Rust target $target: rustup target add $target")
    done
fi
for target in "${targets[@]}"; do
    qemu=${qemu_of[$target]} machine=${machine_of[$target]}
    command -v "$qemu" >/dev/null 2>&1 || continue
    "$qemu" -machine help | grep -qw -- "$machine" ||
        missing+=("QEMU machine $machine: a $qemu that has it (QEMU 7 or later)")
done
if ((${#missing[@]})); then
    echo "firmware.sh: missing, and not installed by this script:" >&2
    printf '  - %s\n' "${missing[@]}" >&2
    exit 2
fi

# --- The host's hashes ---------------------------------------------------------------------

# Lines of `renderer hash`, e.g. `fixed-classic 0x1234abcd`, for every renderer and scene. The
# dev profile reuses what `cargo test` built; the hashes are the same in any profile.
host=$(cd "$root" && cargo run --quiet --example frame_hash && cargo run --quiet --example draw_hash)
declare -A host_hash
while read -r renderer hash; do
    host_hash[$renderer]=$hash
done <<<"$host"

# --- Build, run, compare -------------------------------------------------------------------

# The figures must not depend on where the checkout lies. fixray and its reference are path
# dependencies outside the firmware's workspace, so cargo hashes their absolute path into their
# crates' metadata, and that hash orders and partitions the code: the same sources built from
# two checkouts differed by a few bytes of flash, a few of stack and a tenth of an instruction
# a pixel. So the firmware is built through a link of fixed name to this checkout, held under
# a lock while this script runs (another checkout's run waits). Source paths also end up in the
# firmware (the locations of its panics): the link and cargo's registry are mapped to fixed
# names, added to each target's rustflags from .cargo/config.toml (cargo joins arrays).
link=/tmp/fixray-firmware-checkout
exec 9>>"$link.lock"
if ! flock -w 1800 9; then
    echo "firmware.sh: $link.lock is held by another run for 30 minutes; giving up" >&2
    exit 2
fi
[[ -L $link || ! -e $link ]] || { echo "firmware.sh: $link exists and is not a link" >&2; exit 2; }
ln -sfn "$root" "$link"
if [[ $(readlink "$link") != "$root" ]]; then
    echo "firmware.sh: could not point $link at $root" >&2
    exit 2
fi
manifest="$link/firmware/Cargo.toml"
cargo_home=${CARGO_HOME:-$HOME/.cargo}
remap() { # target: the --config value for it
    printf "target.%s.rustflags=['--remap-path-prefix=%s=/fixray','--remap-path-prefix=%s=/cargo']" \
        "$1" "$link" "$cargo_home"
}

# The binaries that draw the classic scene need fixray's `mirrors-and-glass` feature (their
# `[[bin]]` entries in firmware/Cargo.toml require it): they are built with it, in a target
# directory of their own, and the others without it, as a user's scene without mirrors or
# glass would be.
mapfile -t mirrored < <(awk '/^name = /{ gsub(/"/, "", $3); name = $3 }
    /^required-features = \["mirrors-and-glass"\]/{ print name }' "$firmware/Cargo.toml")
is_mirrored() { [[ " ${mirrored[*]} " == *" $1 "* ]]; }
target_dir_of() { # bin: the target directory it is built in
    if is_mirrored "$1"; then echo "$firmware/target/mirrors"; else echo "$firmware/target"; fi
}
features_of() { # bin: the features it is built with
    if is_mirrored "$1"; then echo mirrors-and-glass; fi
}
for target in "${targets[@]}"; do
    (cd "$firmware" && cargo build --quiet --release --manifest-path "$manifest" \
        --target "$target" --config "$(remap "$target")" --bins 9>&-)
    (cd "$firmware" && cargo build --quiet --release --manifest-path "$manifest" \
        --target "$target" --config "$(remap "$target")" --features mirrors-and-glass \
        --target-dir "$(target_dir_of "${mirrored[0]}")" $(printf -- '--bin %s ' "${mirrored[@]}") 9>&-)
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
declare -A per_pixel_of flash_of ram_of own_of instructions_of # by "target renderer"
names=()
run_firmware() { # target, bin: runs one firmware under QEMU into $log; its exit status in $status
    status=0
    (cd "$firmware" && cargo run --quiet --release --manifest-path "$manifest" --target "$1" \
        --config "$(remap "$1")" --features "$(features_of "$2")" \
        --target-dir "$(target_dir_of "$2")" --bin "$2" 9>&-) \
        >"$log" 2>&1 || status=$?
}
row() { printf '%-28s %-24s %-8s %12s %9s %7s %7s %7s %7s %7s\n' "$@"; }
row target renderer hash instr/frame instr/px flash fixray ram static stack
for target in "${targets[@]}"; do
    for bin in "${bins[@]}"; do
        log="$logs/$target-$bin.txt"
        run_firmware "$target" "$bin"
        renderer=$(field renderer "$(line board=)")
        frame=$(line frame:)
        memory=$(line memory:)
        hash=$(field hash "$frame")
        if ((status != 0)) || [[ -z $hash || -z $memory ]]; then
            row "$target" "${renderer:-$bin}" "FAILED" "exit $status" - - - - - -
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
        own=$(python3 "$root/scripts/own_code.py" "$(target_dir_of "$bin")/$target/release/$bin" || echo -)
        row "$target" "$renderer" "$verdict" "$(field instructions "$frame")" \
            "$(field per_pixel "$frame")" "$(field flash "$memory")" "$own" $((static + stack)) \
            "$static" "$stack"
        per_pixel_of["$target $renderer"]=$(field per_pixel "$frame")
        instructions_of["$target $renderer"]=$(field instructions "$frame")
        flash_of["$target $renderer"]=$(field flash "$memory")
        ram_of["$target $renderer"]=$((static + stack))
        own_of["$target $renderer"]=$own
        if [[ $bin == "${bins[0]}" ]]; then # the counter is the same for every renderer
            counter=$(line counter: | sed 's/^counter: //; s/ instructions_per_tick=.*//')
            per_tick=$(field instructions_per_tick "$(line counter:)")
            calibration=$(line calibration:)
            calibrations+=("$target: $counter, $per_tick instructions per tick;
      a loop of $(field expected "$calibration") counted as $(field measured "$calibration")")
        fi
    done
done

# The static stack bound from `render_row` down (scripts/stack_bound.py): the largest sum of
# stack frames along any chain of calls from the firmware's call of `render_row` (the `fixed`
# binary's, the demo scene), read from its machine code; the panic machinery, whose stack is
# the panic handler's, left out. Painting measures one frame's path; this holds for any.
echo
declare -A bound_of
for target in "${targets[@]}"; do
    case $target in
        riscv*) objdump=riscv64-unknown-elf-objdump ;;
        *) objdump=arm-none-eabi-objdump ;;
    esac
    # fixed_call draws the demo as fixed does, render_row a call of its own (a symbol to
    # start from); its frame must be fixed's, which the run checks.
    log="$logs/$target-fixed_call.txt"
    run_firmware "$target" fixed_call
    verdict=MISMATCH
    [[ $(field hash "$(line frame:)") == "${host_hash[fixed]:-none}" ]] && verdict=match
    [[ $status == 0 && $verdict == match ]] || failed=1
    bound_of[$target]=$(python3 "$root/scripts/stack_bound.py" \
        "$(target_dir_of fixed_call)/$target/release/fixed_call" \
        'FixedCall as .*Renderer>::render_row$' --stop-at 'core::panicking' \
        --objdump "$objdump" | sed -n '1s/ bytes.*//p')
    [[ -n ${bound_of[$target]} ]] || failed=1
    printf '%-28s fixed_call %-8s static stack bound from render_row down: %s bytes\n' \
        "$target" "$verdict" "${bound_of[$target]:-none}"
done

# The drawing layer (firmware/src/bin/draw.rs): each scene drawn onto an Rgb565 display through
# `Viewport::render` and through a `Picture`, with the stack each draw takes below its call,
# measured by painting. Its hashes are examples/draw_hash.rs's; it is not in the README tables.
echo
drow() { printf '%-28s %-8s %-8s %-8s %7s\n' "$@"; }
drow target scene via hash stack
for target in "${targets[@]}"; do
    log="$logs/$target-draw.txt"
    run_firmware "$target" draw
    draws=$(line draw:)
    if ((status != 0)) || (($(grep -c . <<<"$draws") != 4)); then
        drow "$target" draw - FAILED "exit $status"
        sed 's/^/    /' "$log" | tail -n 5 >&2
        failed=1
        continue
    fi
    while read -r draw; do
        scene=$(field scene "$draw")
        verdict=MISMATCH
        [[ $(field hash "$draw") == "${host_hash[draw-$scene]:-none}" ]] && verdict=match
        [[ $verdict == match ]] || failed=1
        drow "$target" "$scene" "$(field via "$draw")" "$verdict" "$(field stack "$draw")"
    done <<<"$draws"
done
echo "stack = bytes below the draw's call (a picture's includes its own row buffer)."

# The animation (firmware/src/bin/animate.rs, firmware/src/animation.rs): a ball rolling across
# the demo floor, each frame redrawn only where `Damage` says it can have changed, then in
# full. Its two hashes (every redrawn span; the last frame) are examples/frame_hash.rs's.
echo
arow() { printf '%-28s %-8s %14s %14s %7s %12s %7s %7s\n' "$@"; }
arow target hash partial/frame full/frame ratio damage/frame px/frame ram
declare -A anim_partial anim_full anim_damage anim_ram
anim_pixels=""
for target in "${targets[@]}"; do
    log="$logs/$target-animate.txt"
    run_firmware "$target" animate
    animate=$(line animate:)
    memory=$(line memory:)
    frames=$(field frames "$animate")
    if ((status != 0)) || [[ -z $frames || -z $memory ]]; then
        arow "$target" FAILED "exit $status" - - - - -
        sed 's/^/    /' "$log" | tail -n 5 >&2
        failed=1
        continue
    fi
    verdict=MISMATCH
    [[ $(field spans_hash "$animate") == "${host_hash[animate-spans]:-none}" &&
        $(field final_hash "$animate") == "${host_hash[animate-final]:-none}" ]] && verdict=match
    [[ $verdict == match ]] || failed=1
    partial=$(($(field partial "$animate") / frames))
    full=$(($(field full "$animate") / frames))
    anim_partial[$target]=$partial
    anim_full[$target]=$full
    anim_damage[$target]=$(($(field damage "$animate") / frames))
    anim_ram[$target]=$(($(field static_ram "$memory") + $(field peak_stack "$memory")))
    anim_pixels=$(($(field pixels "$animate") / frames))
    arow "$target" "$verdict" "$partial" "$full" "$(awk -v p="$partial" -v f="$full" 'BEGIN { printf "%.3f", p / f }')" \
        "${anim_damage[$target]}" "$anim_pixels" "${anim_ram[$target]}"
done
echo "per frame, averaged over the animation's frames; ratio = partial / full; damage = finding the region."

# Progressive passes (firmware/src/bin/progressive.rs, firmware/src/progressive.rs): the demo
# scene in passes from spacing 8 to 1, each pass's instructions against the full frame of the
# `fixed` binary above (a program that draws only passes has no other render_row). The hash of
# every traced pixel, and the digest of the frame the passes leave (each pixel at its place),
# are examples/frame_hash.rs's; the host checks the latter is the full frame's.
echo
prow() { printf '%-28s %-8s %10s %10s %10s %10s %10s %8s %8s\n' "$@"; }
prow target hash pass1 pass2 pass3 pass4 fixed first all
declare -A prog_first prog_all
for target in "${targets[@]}"; do
    log="$logs/$target-progressive.txt"
    run_firmware "$target" progressive
    progressive=$(line progressive:)
    if ((status != 0)) || [[ -z $progressive ]]; then
        prow "$target" FAILED "exit $status" - - - - - -
        sed 's/^/    /' "$log" | tail -n 5 >&2
        failed=1
        continue
    fi
    verdict=MISMATCH
    [[ $(field passes_hash "$progressive") == "${host_hash[progressive-hash]:-none}" &&
        $(field passes_digest "$progressive") == "${host_hash[progressive-digest]:-none}" ]] && verdict=match
    [[ $verdict == match ]] || failed=1
    p=()
    for k in 1 2 3 4; do p+=("$(field "pass$k" "$progressive")"); done
    full=${instructions_of["$target fixed"]:-}
    if [[ -z $full ]]; then
        prow "$target" "$verdict" "${p[@]}" - - -
        continue
    fi
    all=$((p[0] + p[1] + p[2] + p[3]))
    prog_first[$target]=$(awk -v p="${p[0]}" -v f="$full" 'BEGIN { printf "%.2f", 100 * p / f }')
    prog_all[$target]=$(awk -v p="$all" -v f="$full" 'BEGIN { printf "%.1f", 100 * p / f }')
    prow "$target" "$verdict" "${p[@]}" "$full" "${prog_first[$target]} %" "${prog_all[$target]} %"
done
echo "instructions of each pass, and of the fixed binary's frame; first = pass 1 / fixed, all = the four passes / fixed."

echo
echo "host hashes (examples/frame_hash.rs, examples/draw_hash.rs):"
for renderer in "${names[@]}" draw-demo draw-classic animate-spans animate-final progressive-hash progressive-digest; do
    printf '  %-24s %s\n' "$renderer" "${host_hash[$renderer]:-none}"
done
echo "instruction counters (QEMU -icount shift=0), each checked by a loop of known length:"
printf '  %s\n' "${calibrations[@]}"
echo "ram = static RAM + peak stack, in bytes; fixray = the bytes of the ELF's symbols that are fixray's own (scripts/own_code.py);"
echo "instructions count the render_row calls only."
echo "built with $(rustc --version), run on $(qemu-system-arm --version | head -n 1)"

# --- The README's tables -------------------------------------------------------------------

# What the tables show of each renderer, in their order.
cost_rows=(
    "fixed|\`fixed\`: Q16.16, demo scene (Lambert, one light, hard shadows)"
    "reference-f32|\`reference-f32\`: the float baseline, demo"
    "reference-f64|\`reference-f64\`: the f64 reference, demo"
    "fixed-classic|\`fixed-classic\`: Q16.16, classic scene"
    "fixed-classic-noshadow|\`fixed-classic-noshadow\`: classic, no shadow rays"
    "fixed-classic-nomirror|\`fixed-classic-nomirror\`: classic, no mirrors"
    "fixed-classic-opaque|\`fixed-classic-opaque\`: classic, glass without refraction"
    "reference-f32-classic|\`reference-f32-classic\`"
    "reference-f64-classic|\`reference-f64-classic\`"
)
memory_rows=(fixed reference-f32 reference-f64 fixed-classic fixed-classic-opaque reference-f64-classic)

grouped() { # a whole number with its thousands apart, as the README writes them: 46 064
    local n=$1 out=""
    [[ -z $n ]] && { echo "—"; return; }
    while ((${#n} > 3)); do
        out=" ${n: -3}$out"
        n=${n:0:${#n}-3}
    done
    echo "$n$out"
}
per_chip() { # array name, renderer: the figures for every chip, " / " between them
    local -n figures=$1
    local target out=()
    for target in "${targets[@]}"; do
        out+=("$(grouped "${figures["$target $2"]:-}")")
    done
    local IFS=/
    echo "${out[*]}" | sed 's|/| / |g'
}
chip_columns() { # first heading [with-boards]: a table's head, one right-aligned column a chip
    local target
    printf '| %s |' "$1"
    for target in "${targets[@]}"; do
        if [[ ${2:-} == with-boards ]]; then
            printf ' %s (%s) |' "${chip_of[$target]}" "${board_of[$target]}"
        else
            printf ' %s |' "${chip_of[$target]}"
        fi
    done
    printf '\n|---|'
    for target in "${targets[@]}"; do
        printf -- '---:|'
    done
    echo
}
tables() {
    local target entry renderer text chips=()
    for target in "${targets[@]}"; do
        chips+=("${chip_of[$target]}")
    done
    echo "Instructions per pixel at 160 × 128 (\`scripts/firmware.sh --markdown\`, $(rustc --version | cut -d' ' -f1-2), $(qemu-system-arm --version | head -n 1 | sed 's/ emulator version / /; s/ (.*//'), \`opt-level = 3\`, LTO):"
    echo
    chip_columns "renderer, scene" with-boards
    for entry in "${cost_rows[@]}"; do
        renderer=${entry%%|*} text=${entry#*|}
        printf '| %s |' "$text"
        for target in "${targets[@]}"; do
            local value=${per_pixel_of["$target $renderer"]:-}
            [[ -n $value ]] && value=$(printf '%.0f' "$value")
            printf ' %s |' "$(grouped "$value")"
        done
        echo
    done
    echo
    local IFS=/
    local names="${chips[*]}"
    unset IFS
    echo "Flash and RAM (static RAM + peak stack over set-up and frame), bytes, ${names//\// \/ }:"
    echo
    echo "| renderer, scene | flash | fixray's own code | RAM |"
    echo "|---|---|---|---|"
    for renderer in "${memory_rows[@]}"; do
        echo "| \`$renderer\` | $(per_chip flash_of "$renderer") | $(per_chip own_of "$renderer") | $(per_chip ram_of "$renderer") |"
    done
    echo
    local bounds=()
    for target in "${targets[@]}"; do bounds+=("$(grouped "${bound_of[$target]:-}")"); done
    IFS=/
    local bound_list="${bounds[*]}"
    unset IFS
    echo "\`fixed\` and the demo's other binaries are built without the feature \`mirrors-and-glass\`, the classic scene's with it. fixray's own code is the ELF's symbols under \`fixray::\` (\`scripts/own_code.py\`). The static stack bound from a call of \`render_row\` down, over every path its machine code can take (\`scripts/stack_bound.py\` on \`fixed_call\`, which draws as \`fixed\` with \`render_row\` a call of its own; the panic machinery left out): ${bound_list//\// \/ } bytes."
    echo
    local pixels=${anim_pixels:-0} all=$((160 * 128))
    echo "Animation (\`firmware/src/bin/animate.rs\`): a ball of radius 1 rolling across the demo floor at 160 × 128, instructions a frame averaged over its frames, redrawing only the changed region (\`Damage\`) and the whole frame; the partial redraws send $(grouped $((2 * pixels))) bytes of Rgb565 a frame against $(grouped $((2 * all))), $(awk -v p="$pixels" -v a="$all" 'BEGIN { printf "%.1f", 100 * p / a }') %:"
    echo
    chip_columns redraw
    printf '| partial (finding the region included) |'
    for target in "${targets[@]}"; do printf ' %s |' "$(grouped "${anim_partial[$target]:-}")"; done
    echo
    printf '| full |'
    for target in "${targets[@]}"; do printf ' %s |' "$(grouped "${anim_full[$target]:-}")"; done
    echo
    printf '| partial / full |'
    for target in "${targets[@]}"; do
        local p=${anim_partial[$target]:-} f=${anim_full[$target]:-}
        if [[ -n $p && -n $f ]]; then
            printf ' %s %% |' "$(awk -v p="$p" -v f="$f" 'BEGIN { printf "%.1f", 100 * p / f }')"
        else
            printf ' — |'
        fi
    done
    echo
    echo
    echo "Progressive passes (\`firmware/src/bin/progressive.rs\`): the demo scene at 160 × 128 in the four passes of \`Pass::sequence(8)\` (grids of 8 and 4, then the even rows, then the odd rows), instructions against \`fixed\`'s frame:"
    echo
    chip_columns passes
    printf '| the first pass (1/64 of the pixels) / full |'
    for target in "${targets[@]}"; do printf ' %s %% |' "${prog_first[$target]:-—}"; done
    echo
    printf '| all four passes / full |'
    for target in "${targets[@]}"; do printf ' %s %% |' "${prog_all[$target]:-—}"; done
    echo
}
# Known compiler miscompiles (firmware/src/bin/codegen_check.rs, firmware/src/codegen.rs): each
# probe's answer on each chip against rustc's constant evaluation.
echo
crow() { printf '%-28s %-20s %-8s\n' "$@"; }
crow target probe verdict
miscompiled=0
for target in "${targets[@]}"; do
    log="$logs/$target-codegen_check.txt"
    run_firmware "$target" codegen_check
    probes=$(line codegen:)
    if [[ -z $probes ]] || ((status != 0 && status != 5)); then # 5: exit::MISCOMPILED
        crow "$target" codegen_check "FAILED (exit $status)"
        sed 's/^/    /' "$log" | tail -n 5 >&2
        failed=1
        continue
    fi
    while read -r name; do # one row a probe, MISCOMPILED if any of its cases is wrong
        cases=$(grep " probe=$name " <<<"$probes")
        if grep -q 'verdict=WRONG' <<<"$cases"; then
            crow "$target" "$name" MISCOMPILED
            grep 'verdict=WRONG' <<<"$cases" | sed 's/^codegen: /    /' >&2
            miscompiled=1
        else
            crow "$target" "$name" ok
        fi
    done < <(sed -n 's/.* probe=\([^ ]*\) .*/\1/p' <<<"$probes" | sort -u)
done
((miscompiled)) && echo "MISCOMPILED: the toolchain gets a known pattern wrong on that chip (firmware/src/codegen.rs says which, and how it showed)."

mkdir -p "$firmware/target"
tables >"$firmware/target/firmware-tables.md"
echo "the README's tables, from this run: firmware/target/firmware-tables.md"
((markdown)) && cat "$firmware/target/firmware-tables.md" >&3

if ((failed)); then
    verdict=FAILED status=1
elif ((miscompiled)); then
    verdict="ok (every frame matched; a probe shows a known miscompile)" status=0
else
    verdict=ok status=0
fi
echo "firmware.sh: $verdict in ${SECONDS} s"
exit "$status"
