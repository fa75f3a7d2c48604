// PNG files of RGBA8 pixels (filter 0, one IDAT): enough to write renders and read back
// the ones this project wrote.
import { deflateSync, inflateSync } from 'node:zlib';

const CRC = new Int32Array(256).map((_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c;
});

function crc32(buf) {
  let c = -1;
  for (const b of buf) c = CRC[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ -1) >>> 0;
}

function chunk(type, data) {
  const out = Buffer.alloc(12 + data.length);
  out.writeUInt32BE(data.length, 0);
  out.write(type, 4, 'latin1');
  data.copy(out, 8);
  out.writeUInt32BE(crc32(out.subarray(4, 8 + data.length)), 8 + data.length);
  return out;
}

/** A PNG of `width` × `height` RGBA8 pixels, top row first. */
export function encodePng(width, height, rgba) {
  const head = Buffer.alloc(13);
  head.writeUInt32BE(width, 0);
  head.writeUInt32BE(height, 4);
  head.set([8, 6, 0, 0, 0], 8);
  const raw = Buffer.alloc((width * 4 + 1) * height);
  for (let y = 0; y < height; y++) {
    Buffer.from(rgba.buffer, rgba.byteOffset + y * width * 4, width * 4).copy(raw, y * (width * 4 + 1) + 1);
  }
  return Buffer.concat([
    Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]),
    chunk('IHDR', head),
    chunk('IDAT', deflateSync(raw)),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}

/** The pixels of a PNG this module wrote (RGBA8, filter 0): `{ width, height, data }`. */
export function decodePng(buf) {
  let at = 8;
  let width = 0;
  let height = 0;
  const idat = [];
  while (at < buf.length) {
    const len = buf.readUInt32BE(at);
    const type = buf.toString('latin1', at + 4, at + 8);
    const data = buf.subarray(at + 8, at + 8 + len);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[9] !== 6) throw new Error('not an RGBA8 PNG');
    } else if (type === 'IDAT') idat.push(data);
    at += 12 + len;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const out = new Uint8Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    if (raw[y * (width * 4 + 1)] !== 0) throw new Error('PNG row filter other than 0');
    out.set(raw.subarray(y * (width * 4 + 1) + 1, (y + 1) * (width * 4 + 1)), y * width * 4);
  }
  return { width, height, data: out };
}

/** readPixels' bottom-up rows, top row first. */
export function flipRows(width, height, pixels) {
  const out = new Uint8Array(pixels.length);
  for (let y = 0; y < height; y++) {
    out.set(pixels.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
  }
  return out;
}

/**
 * The share of pixels whose every channel is within `tolerance` of the other image's
 * (`within`), the largest difference (`worst`), and — given the width — the same share among
 * the pixels away from edges (`withinAwayFromEdges`): those whose 3×3 neighbourhood in `b`
 * differs from them by at most `edge` in every channel. Rasterisation rules (which pixels an
 * edge or a line covers) and texture filtering at a texel boundary differ between GL
 * implementations within what the GL specifications allow, and such differences land on edges.
 */
export function compare(a, b, tolerance = 3, width = 0, edge = 24) {
  if (a.length !== b.length) throw new Error('images of different sizes');
  const n = a.length / 4;
  const height = width ? n / width : 0;
  let within = 0;
  let worst = 0;
  let smooth = 0;
  let smoothWithin = 0;
  for (let i = 0; i < a.length; i += 4) {
    let d = 0;
    for (let c = 0; c < 4; c++) d = Math.max(d, Math.abs(a[i + c] - b[i + c]));
    if (d <= tolerance) within++;
    worst = Math.max(worst, d);
    if (width && !isEdge(b, width, height, i / 4, edge)) {
      smooth++;
      if (d <= tolerance) smoothWithin++;
    }
  }
  const out = { within: within / n, worst };
  if (width) out.withinAwayFromEdges = smooth ? smoothWithin / smooth : 1;
  return out;
}

function isEdge(img, width, height, p, edge) {
  const x = p % width;
  const y = (p - x) / width;
  for (let dy = -1; dy <= 1; dy++) {
    for (let dx = -1; dx <= 1; dx++) {
      const nx = x + dx;
      const ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      const q = (ny * width + nx) * 4;
      for (let c = 0; c < 4; c++) if (Math.abs(img[q + c] - img[p * 4 + c]) > edge) return true;
    }
  }
  return false;
}
