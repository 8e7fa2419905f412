// The two-core program's frame time, estimated from the single-core program's run in rp2040js:
// each band's rendering and sending measured there, laid out as boards/rp2040-st7789/src/main.rs
// lays them out on two cores.
//
//   node scripts/pico/estimate.mjs RUN.json BANDS.json
//
// RUN.json is scripts/pico/run.mjs's report (the frame's first timer reading, its length),
// BANDS.json scripts/pico/decode.mjs's (the cycle count at each band's CASET and at its last
// pixel byte). From them, for band b:
//   sending S[b]   = from its CASET to its last pixel byte: the address window, packing the
//                    band into the DMA buffer, starting the transfer;
//   rendering R[b] = from the end of the band before (the frame's start for band 0) to its
//                    CASET: rendering the band, and the little between.
// The layout of the two-core program: core 0 renders the even bands and sends every band in
// order; core 1 renders the odd bands into two buffers, taking a buffer back once core 0 has
// sent the band in it. Core 0 sends core 1's band once core 1 has rendered it, and a band's
// commands wait for the band before to leave the wire, which the emulator does not model:
// a band's bytes take BAND_BYTES * 8 bit times at 62.5 MHz, and each command byte its own.
// What it leaves out: the cores contending for the bus and for flash through the shared
// execute-in-place cache, and starting core 1.
//
// On stdout, one line of JSON: the cycles of the measured single-core frame, the single-core
// frame with the wire's waits put back (the same layout on one core), and the two-core frame.

import { readFileSync } from 'node:fs';

const [runPath, bandsPath] = process.argv.slice(2);
if (!runPath || !bandsPath) {
  console.error('usage: node estimate.mjs RUN.json BANDS.json');
  process.exit(2);
}
const run = JSON.parse(readFileSync(runPath, 'utf8'));
const bands = JSON.parse(readFileSync(bandsPath, 'utf8'));

// The program's bus: 62.5 MHz from a 125 MHz system clock, two cycles a bit; a band is
// 240 × 5 pixels of two bytes; each band's window is three commands of 5, 5 and 1 bytes.
const CYCLES_PER_BYTE = 8 * 2;
const BAND_BYTES = 240 * 5 * 2;
const COMMAND_BYTES = 5 + 5 + 1;

const render = bands.map((band, b) => band.start - (b === 0 ? run.frameStart : bands[b - 1].end));
const send = bands.map((band) => band.end - band.start + COMMAND_BYTES * CYCLES_PER_BYTE);
// From the last band's last byte to the frame's second timer reading.
const tail = run.frameStart + run.frameCycles - bands.at(-1).end;

// Core 0's clock after the last band is sent, with core 1 rendering `onCore1(b)` bands.
function layout(onCore1) {
  let core0 = 0;
  let core1 = 0;
  let wireFree = 0;
  const rendered = [];
  const sent = [];
  const core1Bands = [];
  for (let b = 0; b < bands.length; b++) {
    if (onCore1(b)) {
      // Core 1's i-th band waits for its buffer, last used by its band i - 2.
      const i = core1Bands.length;
      const reuse = i >= 2 ? sent[core1Bands[i - 2]] : 0;
      core1 = Math.max(core1, reuse) + render[b];
      rendered[b] = core1;
      core1Bands.push(b);
      core0 = Math.max(core0, rendered[b]);
    } else {
      core0 += render[b];
    }
    // The window's commands wait until the band before has left the wire.
    core0 = Math.max(core0, wireFree) + send[b];
    wireFree = core0 + BAND_BYTES * CYCLES_PER_BYTE;
    sent[b] = core0;
  }
  return core0 + tail;
}

console.log(
  JSON.stringify({
    measuredSingleCore: run.frameCycles,
    renderCycles: render.reduce((a, r) => a + r, 0),
    sendCycles: send.reduce((a, s) => a + s, 0),
    singleCoreWithWire: layout(() => false),
    twoCores: layout((b) => b % 2 === 1),
  }),
);
