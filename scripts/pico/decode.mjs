// Reads what the Pico program sent its display (a stream from scripts/pico/run.mjs) as the
// ST7789 would, and compares the picture with the host's render of the same scene.
//
//   node scripts/pico/decode.mjs STREAM.bin EXPECTED.rgb565 PICTURE.png [BANDS.json]
//
// The decoder is a model of the controller's side of the 4-line SPI bus: a byte counts only
// while chip select is low; with data/command low it is a command, with it high a parameter of
// the last command or, after RAMWR, pixel data. Pixels are 16-bit (COLMOD 0x55), two bytes
// each, the high byte first. CASET and RASET set the address window, RAMWR starts writing at
// its top left; the column counter runs first, then the page counter. MADCTL places the
// counters in the controller's memory of 240 columns by 320 rows: MV exchanges them (the
// column counter then runs down the rows), MX mirrors the columns, MY the rows. So the
// decoder fills the memory as the controller stores it, whatever the program's orientation.
//
// The program's module shows 135 of the memory's columns and 240 of its rows (columns 52 to
// 186, rows 40 to 279) and is held in landscape, its memory's top edge on the left: the
// program's pixel (x, y) is the memory's row 40 + x, column 186 - y. Any write outside that
// part of the memory is an error, as is a command the model does not know, a parameter too
// many, half a pixel, pixels before RAMWR or past the end of the window, or a byte with chip
// select high.
//
// The comparison, with EXPECTED (240 × 135, two bytes a pixel, the high byte first, row by
// row):
//   1. the frame: the picture at the moment every visible pixel has been written once, all
//      of it against the host's, pixel for pixel;
//   2. the end: the picture after the last byte, which has the frame-time text the program
//      draws over the finished frame; every pixel outside the rectangle written after the
//      frame was complete must still equal the host's. The rectangle is reported.
// PICTURE.png gets the end picture (as the memory holds it; an IPS panel, which the program
// sets to invert colours, shows it so). BANDS.json, if named, gets the cycle counts at each
// band's first command byte and last pixel byte, for scripts/pico/estimate.mjs.
//
// Exit status: 0 if both comparisons find no difference, 1 if a pixel differs, 2 if the stream
// breaks the protocol or the frame is never complete.

import { readFileSync, writeFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';

const [streamPath, expectedPath, pngPath, bandsPath] = process.argv.slice(2);
if (!streamPath || !expectedPath || !pngPath) {
  console.error('usage: node decode.mjs STREAM.bin EXPECTED.rgb565 PICTURE.png');
  process.exit(2);
}

// The controller's memory, and the part of it the module shows.
const MEMORY_COLUMNS = 240;
const MEMORY_ROWS = 320;
const VISIBLE = { firstColumn: 52, lastColumn: 186, firstRow: 40, lastRow: 279 };
// The program's picture: landscape, 240 × 135.
const WIDTH = VISIBLE.lastRow - VISIBLE.firstRow + 1;
const HEIGHT = VISIBLE.lastColumn - VISIBLE.firstColumn + 1;
const toPicture = (column, row) => ({ x: row - VISIBLE.firstRow, y: VISIBLE.lastColumn - column });

// The commands the program's driver may send, and how many parameter bytes each takes.
const COMMANDS = {
  0x01: ['SWRESET', 0],
  0x10: ['SLPIN', 0],
  0x11: ['SLPOUT', 0],
  0x13: ['NORON', 0],
  0x20: ['INVOFF', 0],
  0x21: ['INVON', 0],
  0x28: ['DISPOFF', 0],
  0x29: ['DISPON', 0],
  0x2a: ['CASET', 4],
  0x2b: ['RASET', 4],
  0x2c: ['RAMWR', Infinity],
  0x36: ['MADCTL', 1],
  0x3a: ['COLMOD', 1],
};
const MV = 0x20;
const MX = 0x40;
const MY = 0x80;

const fail = (message) => {
  console.error(`decode: ${message}`);
  process.exit(2);
};

const stream = readFileSync(streamPath);
const expected = readFileSync(expectedPath);
if (expected.length !== WIDTH * HEIGHT * 2) {
  fail(`${expectedPath} is ${expected.length} bytes, not ${WIDTH} x ${HEIGHT} pixels of two`);
}

// Memory: -1 where nothing was written.
const memory = new Int32Array(MEMORY_COLUMNS * MEMORY_ROWS).fill(-1);
// The controller's state after a hardware reset, which is the state it starts in here.
let madctl = 0;
let colmod = 0x66;
let inverted = false;
let displayOn = false;
let window = { xs: 0, xe: MEMORY_COLUMNS - 1, ys: 0, ye: MEMORY_ROWS - 1 };
let command = null; // [code, name, takes]
let params = [];
let writing = null; // RAMWR's counters: { c, p, high (the first byte of a pixel, or null) }
const log = []; // the commands, in order, for the report
let pixelsWritten = 0;
let visibleWritten = 0;
const written = new Uint8Array(WIDTH * HEIGHT);
let frame = null; // the picture when the frame is complete
const lateWrites = { minX: Infinity, minY: Infinity, maxX: -1, maxY: -1, pixels: 0 };

function finishCommand() {
  if (!command) return;
  const [code, name, takes] = command;
  if (writing && writing.high !== null) fail(`RAMWR ended with half a pixel`);
  if (takes !== Infinity && params.length !== takes) {
    fail(`${name} (0x${code.toString(16)}) with ${params.length} parameters, not ${takes}`);
  }
  const word = (i) => (params[i] << 8) | params[i + 1];
  switch (name) {
    case 'SWRESET':
      madctl = 0;
      colmod = 0x66;
      inverted = false;
      displayOn = false;
      window = { xs: 0, xe: MEMORY_COLUMNS - 1, ys: 0, ye: MEMORY_ROWS - 1 };
      break;
    case 'INVOFF':
    case 'INVON':
      inverted = name === 'INVON';
      break;
    case 'DISPOFF':
    case 'DISPON':
      displayOn = name === 'DISPON';
      break;
    case 'CASET':
      window.xs = word(0);
      window.xe = word(2);
      break;
    case 'RASET':
      window.ys = word(0);
      window.ye = word(2);
      break;
    case 'MADCTL':
      madctl = params[0];
      break;
    case 'COLMOD':
      colmod = params[0];
      break;
  }
  // The log leaves out CASET and RASET: each RAMWR names its window (counters' ranges) and the
  // pixels it wrote; repeats are counted.
  if (name !== 'CASET' && name !== 'RASET') {
    const entry =
      name === 'RAMWR'
        ? `RAMWR ${window.xe - window.xs + 1} x ${window.ye - window.ys + 1}: ` +
          `${pixelsWritten - writing.start} px`
        : name;
    const last = log.at(-1);
    if (last && last.entry === entry) last.times++;
    else log.push({ entry, times: 1 });
  }
  command = null;
  params = [];
  writing = null;
}

function startCommand(code) {
  finishCommand();
  const known = COMMANDS[code];
  if (!known) fail(`command 0x${code.toString(16)}, which this model of the ST7789 does not know`);
  command = [code, ...known];
  if (known[0] === 'RAMWR') {
    if ((colmod & 0x0f) !== 0x05) fail(`RAMWR with COLMOD 0x${colmod.toString(16)}, not 16-bit`);
    if (window.xs > window.xe || window.ys > window.ye) fail('RAMWR into an empty window');
    writing = { c: window.xs, p: window.ys, high: null, start: pixelsWritten };
  }
}

function writePixel(value) {
  const { c, p } = writing;
  if (p > window.ye) fail('RAMWR past the end of its window');
  let column = madctl & MV ? p : c;
  let row = madctl & MV ? c : p;
  if (column >= MEMORY_COLUMNS || row >= MEMORY_ROWS) {
    fail(`a pixel outside the memory (column ${column}, row ${row})`);
  }
  if (madctl & MX) column = MEMORY_COLUMNS - 1 - column;
  if (madctl & MY) row = MEMORY_ROWS - 1 - row;
  if (
    column < VISIBLE.firstColumn ||
    column > VISIBLE.lastColumn ||
    row < VISIBLE.firstRow ||
    row > VISIBLE.lastRow
  ) {
    fail(`a pixel outside the module's visible part (memory column ${column}, row ${row})`);
  }
  memory[row * MEMORY_COLUMNS + column] = value;
  pixelsWritten++;
  const { x, y } = toPicture(column, row);
  if (frame) {
    lateWrites.minX = Math.min(lateWrites.minX, x);
    lateWrites.minY = Math.min(lateWrites.minY, y);
    lateWrites.maxX = Math.max(lateWrites.maxX, x);
    lateWrites.maxY = Math.max(lateWrites.maxY, y);
    lateWrites.pixels++;
  } else if (!written[y * WIDTH + x]) {
    written[y * WIDTH + x] = 1;
    if (++visibleWritten === WIDTH * HEIGHT) frame = picture();
  }
  // The column counter first, then the page counter.
  if (++writing.c > window.xe) {
    writing.c = window.xs;
    writing.p++;
  }
}

// The program's picture, from the memory: Rgb565 values, -1 where nothing was written.
function picture() {
  const pixels = new Int32Array(WIDTH * HEIGHT);
  for (let row = VISIBLE.firstRow; row <= VISIBLE.lastRow; row++) {
    for (let column = VISIBLE.firstColumn; column <= VISIBLE.lastColumn; column++) {
      const { x, y } = toPicture(column, row);
      pixels[y * WIDTH + x] = memory[row * MEMORY_COLUMNS + column];
    }
  }
  return pixels;
}

// The cycles the program spent sending the bands (the full-width windows): from each window's
// first command byte (CASET) to its last pixel byte, which includes packing the band into the
// DMA buffer. The emulated DMA moves a band at once, so the wire's time is not in it.
const bands = { count: 0, cycles: 0, first: null, last: null, each: [] };
let windowStart = null;
let lastByteCycles = 0;

let unselected = 0;
for (let i = 0; i + 5 < stream.length; i += 6) {
  const pins = stream[i];
  const byte = stream[i + 1];
  const cycles = stream.readUInt32LE(i + 2);
  if (!(pins & 1) && byte === 0x2a) {
    endBand();
    windowStart = cycles;
  }
  lastByteCycles = cycles;
  if (!(pins & 2)) {
    unselected++;
    continue;
  }
  if (!(pins & 1)) {
    startCommand(byte);
  } else if (writing) {
    if (writing.high === null) {
      writing.high = byte;
    } else {
      writePixel((writing.high << 8) | byte);
      writing.high = null;
    }
  } else if (command) {
    params.push(byte);
    if (params.length > command[2]) fail(`${command[1]} with more than ${command[2]} parameters`);
  } else {
    fail('a data byte before any command');
  }
}
endBand();
finishCommand();

// Called at each CASET and at the end: closes the window before, if it was a band.
function endBand() {
  const band = writing && window.xe - window.xs + 1 === WIDTH;
  if (band && windowStart !== null) {
    bands.count++;
    bands.cycles += lastByteCycles - windowStart;
    bands.first ??= windowStart;
    bands.last = lastByteCycles;
    bands.each.push({ start: windowStart, end: lastByteCycles });
  }
  windowStart = null;
}

if (unselected) fail(`${unselected} bytes sent with chip select high`);
if (!frame) {
  fail(`the frame is not complete: ${visibleWritten} of ${WIDTH * HEIGHT} pixels written`);
}
const end = picture();

// --- Compare ----------------------------------------------------------------------------------

const want = (i) => expected.readUInt16BE(2 * i);
let frameDiffer = 0;
for (let i = 0; i < WIDTH * HEIGHT; i++) if (frame[i] !== want(i)) frameDiffer++;
const inText = (i) => {
  const x = i % WIDTH;
  const y = Math.floor(i / WIDTH);
  return (
    x >= lateWrites.minX && x <= lateWrites.maxX && y >= lateWrites.minY && y <= lateWrites.maxY
  );
};
let outsideDiffer = 0;
let insideDiffer = 0;
for (let i = 0; i < WIDTH * HEIGHT; i++) {
  if (end[i] === want(i)) continue;
  if (inText(i)) insideDiffer++;
  else outsideDiffer++;
}

const text =
  lateWrites.pixels > 0
    ? `x ${lateWrites.minX}..${lateWrites.maxX}, y ${lateWrites.minY}..${lateWrites.maxY} ` +
      `(${lateWrites.maxX - lateWrites.minX + 1} x ${lateWrites.maxY - lateWrites.minY + 1}, ` +
      `${lateWrites.pixels} pixels written)`
    : 'none';
const commands = log.map((e) => (e.times > 1 ? `${e.entry} (${e.times} times)` : e.entry));
console.log(`decode: commands: ${commands.join(', ')}`);
console.log(
  `decode: MADCTL 0x${madctl.toString(16).padStart(2, '0')}, COLMOD 0x${colmod.toString(16)}, ` +
    `colours ${inverted ? 'inverted' : 'not inverted'}, display ${displayOn ? 'on' : 'off'}; ` +
    `${pixelsWritten} pixels written`,
);
if (bands.count) {
  console.log(
    `decode: ${bands.count} bands, from the first's CASET to the last's last pixel ` +
      `${bands.last - bands.first} cycles, of which ${bands.cycles} sending them ` +
      `(the address window, packing, starting the DMA)`,
  );
}
console.log(
  `decode: the frame, complete: ${frameDiffer} of ${WIDTH * HEIGHT} pixels differ ` +
    `from the host's`,
);
console.log(`decode: written after it (the frame-time text): ${text}`);
console.log(
  `decode: the end picture: ${outsideDiffer} pixels differ outside that rectangle, ` +
    `${insideDiffer} inside it (the text)`,
);

if (bandsPath) writeFileSync(bandsPath, JSON.stringify(bands.each));

// --- The end picture as a PNG: 8-bit RGB, no filter -------------------------------------------

const rows = Buffer.alloc(HEIGHT * (1 + 3 * WIDTH));
for (let y = 0; y < HEIGHT; y++) {
  for (let x = 0; x < WIDTH; x++) {
    const value = end[y * WIDTH + x];
    const at = y * (1 + 3 * WIDTH) + 1 + 3 * x;
    // Each channel widened to 8 bits by repeating its top bits, as embedded-graphics does.
    const r = (value >> 11) & 0x1f;
    const g = (value >> 5) & 0x3f;
    const b = value & 0x1f;
    rows[at] = (r << 3) | (r >> 2);
    rows[at + 1] = (g << 2) | (g >> 4);
    rows[at + 2] = (b << 3) | (b >> 2);
  }
}
const crcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
const crc32 = (bytes) => {
  let c = 0xffffffff;
  for (const byte of bytes) c = crcTable[(c ^ byte) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
};
const chunk = (kind, body) => {
  const head = Buffer.alloc(4);
  head.writeUInt32BE(body.length);
  const kindBody = Buffer.concat([Buffer.from(kind, 'ascii'), body]);
  const tail = Buffer.alloc(4);
  tail.writeUInt32BE(crc32(kindBody));
  return Buffer.concat([head, kindBody, tail]);
};
const header = Buffer.alloc(13);
header.writeUInt32BE(WIDTH, 0);
header.writeUInt32BE(HEIGHT, 4);
header.set([8, 2, 0, 0, 0], 8); // 8 bits a channel, RGB, deflate, no filter, no interlace
writeFileSync(
  pngPath,
  Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('IDAT', deflateSync(rows, { level: 9 })),
    chunk('IEND', Buffer.alloc(0)),
  ]),
);
console.log(`decode: the end picture as a PNG: ${pngPath}`);

process.exit(frameDiffer || outsideDiffer ? 1 : 0);
