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
cd "$root/firmware"
cargo build --release --quiet --target "$target" --bin "$bin"
elf="target/$target/release/$bin"
case $target in
  thumbv6m-none-eabi) qemu=(qemu-system-arm -machine microbit); a2l=arm-none-eabi-addr2line ;;
  thumbv7em-none-eabihf) qemu=(qemu-system-arm -machine mps2-an386); a2l=arm-none-eabi-addr2line ;;
  riscv32imc-unknown-none-elf) qemu=(qemu-system-riscv32 -machine virt -bios none); a2l=addr2line ;;
  *) echo "profile.sh: unknown target $target" >&2; exit 2 ;;
esac
command -v "$a2l" >/dev/null || { echo "profile.sh: needs $a2l" >&2; exit 2; }
fifo=$(mktemp -u); mkfifo "$fifo"; trap 'rm -f "$fifo"' EXIT
python3 "$root/scripts/profile.py" "$fifo" "$elf" "$a2l" "$@" &
timeout 600 "${qemu[@]}" -icount shift=0 -semihosting-config enable=on,target=native \
  -display none -monitor none -serial none -d in_asm,exec,nochain -D "$fifo" -kernel "$elf" >/dev/null
wait
