// Runs fixray's Raspberry Pi Pico program (boards/rp2040-st7789, built with its `single-core`
// feature) in rp2040js, the RP2040 emulator, and records every byte it sends the display.
//
//   node scripts/pico/run.mjs PROGRAM.elf STREAM.bin
//
// STREAM.bin gets six bytes per byte on the SPI bus, in order: the pins' levels as it left
// (bit 0: data/command, GP16, high for data; bit 1: chip select, GP17, low for selected), the
// byte, and the core's cycle count then (32 bits, little-endian). scripts/pico/decode.mjs
// reads it as the ST7789 would. On stdout, one line of JSON: the cycles the program ran, the
// cycles between its two readings of the frame timer (the frame) and in the stand-in ROM, the
// bytes sent, and why the run stopped.
//
// The run takes the first frame and no more. After the frame and the frame-time text over it,
// the program pauses, then orbits the camera and draws other views, which are not the host's
// picture: its first read of the timer after the frame's end reading (the pause's) ends the
// run, as does sleeping for good.
//
// rp2040js emulates one Cortex-M0+ core (core 1 never runs) and ships no boot ROM. So this
// script starts the core where the boot ROM and the second-stage boot loader would leave it:
// at the program's vector table after the 256-byte boot loader, with VTOR, SP and PC set from
// it, flash readable as it is once execute-in-place is set up. rp2040-hal calls five ROM
// routines through the ROM's function table (memset, memset4, memcpy, memcpy44, clz32); the
// script puts a small stand-in ROM in their place, below, written for this script, so the
// program's calls work and the core executes (and counts the cycles of) code that does what
// the ROM's does. Its cycle counts are not the real ROM's; the JSON says how many cycles the
// program spent in it.

import { readFileSync, writeFileSync } from 'node:fs';
import { RP2040, GPIOPinState } from 'rp2040js';

const [elfPath, streamPath] = process.argv.slice(2);
if (!elfPath || !streamPath) {
  console.error('usage: node run.mjs PROGRAM.elf STREAM.bin');
  process.exit(2);
}

// The program's pins (boards/rp2040-st7789/src/main.rs): data/command and chip select.
const DC_PIN = 16;
const CS_PIN = 17;
// The program runs the system clock at 125 MHz; the emulated timer counts microseconds of
// simulated time, which advances by one such period per cycle.
const CLK_SYS_HZ = 125_000_000;
const NANOS_PER_CYCLE = 1e9 / CLK_SYS_HZ;
// A program that never finishes its frame stops here: far more cycles than a frame and the
// driver's start-up delays take.
const CYCLE_LIMIT = 400_000_000;
// TIMERAWH, the timer's high word: rp2040-hal's `Timer::get_counter` reads it, its
// microsecond delays (the driver's start-up, the pause after the frame) read only the low
// word, TIMERAWL. So the program's reads of the high word are the frame's start and end.
const TIMERAWH = 0x24;
const TIMERAWL = 0x28;
// rp2040-hal's `get_counter` reads the high word twice or more, a few cycles apart, around the
// low word: reads closer than this are one reading of the timer.
const READING_CYCLES = 100;
const TIMER_BASE = 0x40054000;
const FLASH = 0x10000000;
const BOOT2_BYTES = 0x100;

// Its default clock is simulated time, which only this script's loop below advances.
const mcu = new RP2040();
mcu.logger.currentLogLevel = 2; // warnings and errors only (rp2040js's LogLevel.Warn)

// --- The stand-in ROM ----------------------------------------------------------------------
//
// The RP2040's ROM keeps, at 0x14, a 16-bit pointer to its table of functions, and at 0x18 a
// 16-bit pointer to the function that looks a two-letter code up in such a table; a table is
// pairs of 16-bit (code, address) ending with a zero code. rp2040-hal calls the lookup, then
// the function it returns. The functions below behave as the datasheet describes the ROM's
// (return values included); assembled for the Cortex-M0+ (Thumb), one halfword a line.
const ROM_CODE = 0x100;
const ROM_TABLE = 0x80;
const romCode = [
  // rom_table_lookup(table r0, code r1) -> address, or 0
  0x8802, //  0 loop: ldrh r2, [r0]
  0x2a00, //  2   cmp r2, #0
  0xd003, //  4   beq none
  0x428a, //  6   cmp r2, r1
  0xd003, //  8   beq found
  0x3004, //  a   adds r0, #4
  0xe7f8, //  c   b loop
  0x2000, //  e none: movs r0, #0
  0x4770, // 10   bx lr
  0x8840, // 12 found: ldrh r0, [r0, #2]
  0x4770, // 14   bx lr
  // memset(ptr r0, c r1, n r2) -> ptr
  0x2300, // 16   movs r3, #0
  0x4293, // 18 loop: cmp r3, r2
  0xd002, // 1a   beq done
  0x54c1, // 1c   strb r1, [r0, r3]
  0x3301, // 1e   adds r3, #1
  0xe7fa, // 20   b loop
  0x4770, // 22 done: bx lr
  // memset4(ptr r0, c r1, n r2) -> ptr: whole words, then any bytes left
  0xb510, // 24   push {r4, lr}
  0xb2c9, // 26   uxtb r1, r1
  0x020b, // 28   lsls r3, r1, #8
  0x4319, // 2a   orrs r1, r3
  0x040b, // 2c   lsls r3, r1, #16
  0x4319, // 2e   orrs r1, r3
  0x2300, // 30   movs r3, #0
  0x0894, // 32   lsrs r4, r2, #2
  0x00a4, // 34   lsls r4, r4, #2
  0x42a3, // 36 words: cmp r3, r4
  0xd002, // 38   beq bytes
  0x50c1, // 3a   str r1, [r0, r3]
  0x3304, // 3c   adds r3, #4
  0xe7fa, // 3e   b words
  0x4293, // 40 bytes: cmp r3, r2
  0xd002, // 42   beq done
  0x54c1, // 44   strb r1, [r0, r3]
  0x3301, // 46   adds r3, #1
  0xe7fa, // 48   b bytes
  0xbd10, // 4a done: pop {r4, pc}
  // memcpy(dest r0, src r1, n r2) -> dest
  0xb510, // 4c   push {r4, lr}
  0x2300, // 4e   movs r3, #0
  0x4293, // 50 loop: cmp r3, r2
  0xd003, // 52   beq done
  0x5ccc, // 54   ldrb r4, [r1, r3]
  0x54c4, // 56   strb r4, [r0, r3]
  0x3301, // 58   adds r3, #1
  0xe7f9, // 5a   b loop
  0xbd10, // 5c done: pop {r4, pc}
  // memcpy44(dest r0, src r1, n r2) -> dest: whole words, then any bytes left
  0xb530, // 5e   push {r4, r5, lr}
  0x2300, // 60   movs r3, #0
  0x0894, // 62   lsrs r4, r2, #2
  0x00a4, // 64   lsls r4, r4, #2
  0x42a3, // 66 words: cmp r3, r4
  0xd003, // 68   beq bytes
  0x58cd, // 6a   ldr r5, [r1, r3]
  0x50c5, // 6c   str r5, [r0, r3]
  0x3304, // 6e   adds r3, #4
  0xe7f9, // 70   b words
  0x4293, // 72 bytes: cmp r3, r2
  0xd003, // 74   beq done
  0x5ccd, // 76   ldrb r5, [r1, r3]
  0x54c5, // 78   strb r5, [r0, r3]
  0x3301, // 7a   adds r3, #1
  0xe7f9, // 7c   b bytes
  0xbd30, // 7e done: pop {r4, r5, pc}
  // clz32(x r0) -> leading zeros, 32 for 0: halve the width searched five times
  0x2100, // 80   movs r1, #0
  0x0c02, // 82   lsrs r2, r0, #16
  0xd101, // 84   bne 1f
  0x3110, // 86   adds r1, #16
  0x0400, // 88   lsls r0, r0, #16
  0x0e02, // 8a 1: lsrs r2, r0, #24
  0xd101, // 8c   bne 2f
  0x3108, // 8e   adds r1, #8
  0x0200, // 90   lsls r0, r0, #8
  0x0f02, // 92 2: lsrs r2, r0, #28
  0xd101, // 94   bne 3f
  0x3104, // 96   adds r1, #4
  0x0100, // 98   lsls r0, r0, #4
  0x0f82, // 9a 3: lsrs r2, r0, #30
  0xd101, // 9c   bne 4f
  0x3102, // 9e   adds r1, #2
  0x0080, // a0   lsls r0, r0, #2
  0x0fc2, // a2 4: lsrs r2, r0, #31
  0xd101, // a4   bne 5f
  0x3101, // a6   adds r1, #1
  0x0040, // a8   lsls r0, r0, #1
  0x2800, // aa 5: cmp r0, #0 (x was 0: 31 so far)
  0xd100, // ac   bne 6f
  0x3101, // ae   adds r1, #1
  0x4608, // b0 6: mov r0, r1
  0x4770, // b2   bx lr
];
// The codes as rp2040-hal asks for them (two ASCII letters, the first in the low byte), and
// each function's offset in romCode; addresses are odd, as Thumb function pointers are.
const romFunctions = [
  ['MS', 0x16],
  ['S4', 0x24],
  ['MC', 0x4c],
  ['C4', 0x5e],
  ['L3', 0x80],
];
const ROM_LOOKUP = ROM_CODE;

function installRom() {
  const rom = new DataView(mcu.bootrom.buffer);
  rom.setUint16(0x14, ROM_TABLE, true);
  rom.setUint16(0x18, ROM_LOOKUP | 1, true);
  romFunctions.forEach(([code, offset], i) => {
    rom.setUint16(ROM_TABLE + 4 * i, code.charCodeAt(0) | (code.charCodeAt(1) << 8), true);
    rom.setUint16(ROM_TABLE + 4 * i + 2, (ROM_CODE + offset) | 1, true);
  });
  rom.setUint16(ROM_TABLE + 4 * romFunctions.length, 0, true);
  romCode.forEach((halfword, i) => rom.setUint16(ROM_CODE + 2 * i, halfword, true));
}
const ROM_END = ROM_CODE + 2 * romCode.length;

// --- The program ---------------------------------------------------------------------------

// An ELF32 file's loadable segments, each at its load (physical) address: the program's
// flash image, .data's initial values included.
function loadElf(path) {
  const elf = readFileSync(path);
  if (elf.readUInt32BE(0) !== 0x7f454c46 || elf[4] !== 1 || elf[5] !== 1) {
    throw new Error(`${path} is not a 32-bit little-endian ELF file`);
  }
  const phoff = elf.readUInt32LE(0x1c);
  const phentsize = elf.readUInt16LE(0x2a);
  const phnum = elf.readUInt16LE(0x2c);
  let loaded = 0;
  for (let i = 0; i < phnum; i++) {
    const at = phoff + i * phentsize;
    const [type, offset, , paddr, filesz] = [0, 4, 8, 12, 16].map((o) => elf.readUInt32LE(at + o));
    if (type !== 1 || filesz === 0) continue; // PT_LOAD with bytes in the file
    if (paddr < FLASH || paddr + filesz > FLASH + mcu.flash.length) {
      throw new Error(`a segment at 0x${paddr.toString(16)} is not in flash`);
    }
    mcu.flash.set(elf.subarray(offset, offset + filesz), paddr - FLASH);
    loaded += filesz;
  }
  return loaded;
}

installRom();
const loaded = loadElf(elfPath);
const core = mcu.core;
const vectors = FLASH + BOOT2_BYTES;
core.VTOR = vectors;
core.SP = mcu.readUint32(vectors);
core.PC = mcu.readUint32(vectors + 4) & ~1;

// --- What goes to the display ----------------------------------------------------------------

const stream = [];
const spi = mcu.spi[0];
const pins = mcu.gpio;
// rp2040js hands each byte to onTransmit as the SPI peripheral starts shifting it out, and
// the transfer is complete when we say so: at once (the emulator has no bus timing).
spi.onTransmit = (value) => {
  const dc = pins[DC_PIN].value === GPIOPinState.High ? 1 : 0;
  const selected = pins[CS_PIN].value === GPIOPinState.Low ? 2 : 0;
  const cycles = core.cycles;
  stream.push(dc | selected, value & 0xff, cycles & 0xff, (cycles >>> 8) & 0xff);
  stream.push((cycles >>> 16) & 0xff, (cycles >>> 24) & 0xff);
  spi.completeTransmit(0);
};

// The frame timer's readings: at the first read of TIMERAWH of each, the cycle count and the
// cycles spent in the stand-in ROM so far; `end`, the cycle count at its last read. The frame
// is from the first reading to the second. A read of either word after those two, and apart
// from the second, is the pause after the frame: `pastFrame` stops the run there.
const readings = [];
let pastFrame = false;
const timer = mcu.findPeripheral(TIMER_BASE);
const readTimer = timer.readUint32.bind(timer);
timer.readUint32 = (offset) => {
  const last = readings.at(-1);
  const apart = !last || core.cycles - last.end >= READING_CYCLES;
  if (readings.length === 2 && apart && (offset === TIMERAWH || offset === TIMERAWL)) {
    pastFrame = true;
  } else if (offset === TIMERAWH) {
    if (apart) readings.push({ start: core.cycles, rom: romCycles, end: core.cycles });
    else last.end = core.cycles;
  }
  return readTimer(offset);
};

// --- Run ----------------------------------------------------------------------------------------

const clock = mcu.clock;
let romCycles = 0;
let stopped = 'cycle limit';
const wallStart = process.hrtime.bigint();
while (core.cycles < CYCLE_LIMIT) {
  if (pastFrame) {
    stopped = 'past the frame';
    break;
  }
  if (core.waiting) {
    // Asleep (wfi/wfe). Only a timer alarm or a DMA transfer could wake it; with none due, the
    // program sleeps for good: after its frame, or stuck waiting for core 1.
    const next = clock.nanosToNextAlarm;
    if (!clock.nextAlarm) {
      stopped = 'asleep';
      break;
    }
    clock.tick(next);
    core.cycles += Math.ceil(next / NANOS_PER_CYCLE);
    continue;
  }
  const inRom = core.PC < ROM_END;
  const cycles = core.executeInstruction();
  if (inRom) romCycles += cycles;
  clock.tick(cycles * NANOS_PER_CYCLE);
}
const wallSeconds = Number(process.hrtime.bigint() - wallStart) / 1e9;

writeFileSync(streamPath, Uint8Array.from(stream));

const frame =
  readings.length === 2
    ? {
        start: readings[0].start,
        cycles: readings[1].start - readings[0].start,
        rom: readings[1].rom - readings[0].rom,
      }
    : null;
console.log(
  JSON.stringify({
    loadedBytes: loaded,
    stopped,
    pc: `0x${core.PC.toString(16)}`,
    cycles: core.cycles,
    timerReadings: readings.length,
    frameStart: frame?.start ?? null,
    frameCycles: frame?.cycles ?? null,
    frameRomCycles: frame?.rom ?? null,
    romCycles,
    spiBytes: stream.length / 6,
    wallSeconds: Math.round(wallSeconds * 10) / 10,
  }),
);
