#!/usr/bin/env bash
# The demo scene on an emulated display, end to end: the firmware firmware/src/bin/oled.rs
# draws it through fixray's Viewport onto the 128 × 64, 16-grey OLED (an SSD0323 controller on
# SSI0) of QEMU's lm3s6965evb; QEMU's monitor captures the panel (`screendump`, a 512 × 256
# PPM: each panel pixel a 4 × 4 block, grey level n as 17 · n); the capture must equal, pixel
# for pixel, what the host's render of the same scene through the same Viewport into an
# in-memory Gray4 display gives (examples/oled.rs, converted as QEMU draws the panel).
#
# Usage: scripts/oled.sh [--png FILE]
#
# It writes the capture, the host's expected picture and QEMU's log to firmware/target/oled/,
# and the capture as a PNG to firmware/target/oled/oled.png, or to FILE with --png (the
# README's picture: scripts/oled.sh --png docs/oled.png). QEMU runs headless (`-display none`)
# under `timeout`, its monitor on a unix socket.
#
# Exit status: 0 if the capture matches, 1 if it differs or the firmware fails, 2 if something
# it needs is missing.
set -euo pipefail
export LC_ALL=C

root=$(cd "$(dirname "$0")/.." && pwd)
png=""
case ${1:-} in
    --png) png=${2:?usage: scripts/oled.sh [--png FILE]}; [[ $png == /* ]] || png="$PWD/$png" ;;
    "") ;;
    *) echo "usage: scripts/oled.sh [--png FILE]" >&2; exit 2 ;;
esac

target=thumbv7m-none-eabi
machine=lm3s6965evb
missing=()
for command in cargo rustc qemu-system-arm python3 timeout; do
    command -v "$command" >/dev/null 2>&1 || missing+=("$command")
done
if command -v rustc >/dev/null 2>&1 &&
    [[ ! -d "$(rustc --print sysroot)/lib/rustlib/$target/lib" ]]; then
    missing+=("the Rust target $target: rustup target add $target")
fi
if command -v qemu-system-arm >/dev/null 2>&1 &&
    ! qemu-system-arm -machine help | grep -qw "$machine"; then
    missing+=("QEMU machine $machine")
fi
if ((${#missing[@]})); then
    echo "oled.sh: missing, and not installed by this script:" >&2
    printf '  - %s\n' "${missing[@]}" >&2
    exit 2
fi

out="$root/firmware/target/oled"
mkdir -p "$out"
rm -f "$out/capture.ppm" "$out/expected.ppm" "$out/qemu.log"
[[ -n $png ]] || png="$out/oled.png"

# --- The host's picture, and the firmware --------------------------------------------------

(cd "$root" && cargo run --quiet --example oled -- "$out/expected.ppm")
(cd "$root/firmware" &&
    cargo build --quiet --release --target "$target" --features oled --bin oled)
elf="$root/firmware/target/$target/release/oled"

# --- Run, wait for the picture, capture it -------------------------------------------------

# A unix socket path must be short (108 bytes): a fresh directory under /tmp.
sockets=$(mktemp -d)
monitor="$sockets/monitor"
qemu_pid=""
cleanup() {
    [[ -n $qemu_pid ]] && kill "$qemu_pid" 2>/dev/null || true
    rm -rf "$sockets"
}
trap cleanup EXIT

timeout 120 qemu-system-arm -machine "$machine" \
    -semihosting-config enable=on,target=native -display none -serial none \
    -monitor "unix:$monitor,server=on,wait=off" -kernel "$elf" >"$out/qemu.log" 2>&1 &
qemu_pid=$!

# The firmware says `oled: drawn ...` once the last row is on the panel, then sleeps.
for ((i = 0; i < 600; i++)); do
    grep -q '^oled: drawn' "$out/qemu.log" && break
    if ! kill -0 "$qemu_pid" 2>/dev/null; then
        echo "oled.sh: QEMU ended before the picture was drawn:" >&2
        sed 's/^/    /' "$out/qemu.log" >&2
        exit 1
    fi
    sleep 0.1
done
if ! grep -q '^oled: drawn' "$out/qemu.log"; then
    echo "oled.sh: the firmware did not finish drawing within a minute:" >&2
    sed 's/^/    /' "$out/qemu.log" >&2
    exit 1
fi

# Ask the monitor for the screendump, wait until it is written whole, then quit.
python3 - "$monitor" "$out/capture.ppm" <<'PY'
import os, socket, sys, time
monitor, capture = sys.argv[1:3]
size = 512 * 256 * 3 + len(b"P6\n512 256\n255\n")
with socket.socket(socket.AF_UNIX) as s:
    s.connect(monitor)
    s.sendall(f"screendump {capture}\n".encode())
    deadline = time.monotonic() + 30
    while not (os.path.exists(capture) and os.path.getsize(capture) >= size):
        if time.monotonic() > deadline:
            sys.exit("oled.sh: no screendump from QEMU's monitor within 30 s")
        time.sleep(0.05)
    # QEMU closes the monitor as it quits: read until then, or the quit may be lost with
    # the connection.
    s.sendall(b"quit\n")
    s.settimeout(30)
    while s.recv(4096):
        pass
PY
wait "$qemu_pid" || true
qemu_pid=""

# --- Compare, and keep the capture as a PNG ------------------------------------------------

python3 - "$out/capture.ppm" "$out/expected.ppm" "$png" <<'PY'
import struct, sys, zlib

def ppm(path):
    """Width, height and the RGB bytes of a binary PPM with maxval 255."""
    data = open(path, "rb").read()
    fields, at = [], 0
    while len(fields) < 4:  # magic, width, height, maxval, each followed by whitespace
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    at += 1
    if fields[0] != b"P6" or fields[3] != b"255":
        sys.exit(f"oled.sh: {path} is not a binary PPM with maxval 255")
    width, height = int(fields[1]), int(fields[2])
    pixels = data[at:at + width * height * 3]
    if len(pixels) != width * height * 3:
        sys.exit(f"oled.sh: {path} is cut short")
    return width, height, pixels

capture_path, expected_path, png_path = sys.argv[1:4]
width, height, capture = ppm(capture_path)
expected = ppm(expected_path)
if (width, height) != expected[:2]:
    sys.exit(f"oled.sh: the capture is {width} x {height}, the host's picture "
             f"{expected[0]} x {expected[1]}")
differing = sum(capture[i:i + 3] != expected[2][i:i + 3] for i in range(0, len(capture), 3))
print(f"oled.sh: capture {width} x {height} against the host's render: "
      f"{differing} of {width * height} pixels differ")

# The PNG: 8-bit RGB, one filter byte (none) a row.
rows = b"".join(b"\0" + capture[y * width * 3:(y + 1) * width * 3] for y in range(height))
def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
with open(png_path, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows, 9))
            + chunk(b"IEND", b""))
print(f"oled.sh: the capture as a PNG: {png_path}")
sys.exit(1 if differing else 0)
PY
