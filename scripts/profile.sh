#!/usr/bin/env bash
# Profiles one firmware binary under QEMU: instructions per pixel by function (or by inlined
# chain and source line), from an execution log of every translated block.
#
# Usage: scripts/profile.sh TARGET BIN [profile.py options]
#   scripts/profile.sh thumbv7em-none-eabihf fixed
#   scripts/profile.sh thumbv6m-none-eabi fixed --depth 3 --lines --top 60
#
# Needs what scripts/firmware.sh needs, plus an addr2line for the target: binutils-arm-none-eabi
# (apt-get install binutils-arm-none-eabi) for the Arm chips, the host's binutils for RV32.
# The log is streamed through a FIFO, never written out (it runs to gigabytes), and the counts
# include QEMU's whole run; only what ran inside fixray's code is reported.
set -euo pipefail
target=${1:?target}; bin=${2:?binary}; shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
elf="target/$target/release/$bin"
# The target's QEMU machine and options: firmware/targets.tsv, as scripts/firmware.sh reads it.
row=$(awk -F '\t' -v t="$target" '$1 == t' "$root/firmware/targets.tsv")
[[ -n $row ]] || { echo "profile.sh: $target is not in firmware/targets.tsv" >&2; exit 2; }
IFS=$'\t' read -r _ qemu_bin machine options _ <<<"$row"
[[ $options == - ]] && options=""
# shellcheck disable=SC2206 # the options are words
qemu=("$qemu_bin" -machine "$machine" $options)
case $target in
  thumb*) a2l=arm-none-eabi-addr2line ;;
  *) a2l=addr2line ;;
esac
command -v "$a2l" >/dev/null || { echo "profile.sh: needs $a2l" >&2; exit 2; }
cd "$root/firmware"
cargo build --release --quiet --target "$target" --bin "$bin"
fifo=$(mktemp -u); mkfifo "$fifo"; trap 'rm -f "$fifo"' EXIT
python3 "$root/scripts/profile.py" "$fifo" "$elf" "$a2l" "$@" &
timeout 600 "${qemu[@]}" -icount shift=0 -semihosting-config enable=on,target=native \
  -display none -monitor none -serial none -d in_asm,exec,nochain -D "$fifo" -kernel "$elf" >/dev/null
wait
