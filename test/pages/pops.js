// Counting the pixels that pop in a slow dolly (test/browser/creases.test.js, through
// test/pages/creases.js): pure, so a Node test holds it to images built by hand
// (test/node/pops.test.js).
//
// A frame is RGB in output steps (the displayed value times 255, before rounding), rows of `width`.
// For each pixel, channel and pair of consecutive frames k, the change Δ_k; the pixel's steady
// change is the median of its Δ_k over the dolly (a slow dolly moves the image under a pixel at a
// steady rate; a switch changes it in one pair); its departure in pair k is the largest over its
// channels of |Δ_k − median|. A pixel pops in pair k when its departure is POP_STEPS or more and
// is not explained: the explaining dolly (the same frames drawn without scattering: the light as
// three rasterises it) departs less than EXPLAINED_STEPS in that pair at the pixel and at each of
// its 8 neighbours.

/** A pop: a whole output step. */
export const POP_STEPS = 1;
/** A pair's departure of the light itself that explains a pop at the pixel or beside it: half a step. */
export const EXPLAINED_STEPS = 0.5;

/**
 * @param {Float32Array[]} images RGB per pixel, `width` × `height`, one per frame (at least 3)
 * @returns {{ width: number, height: number, pairs: number, departures: Float32Array }} departures[p · pairs + k]
 */
export function popDepartures(images, width, height) {
  const pairs = images.length - 1;
  if (!(pairs >= 2)) throw new RangeError(`popDepartures needs at least 3 frames, got ${images.length}`);
  const pixels = width * height;
  const departures = new Float32Array(pixels * pairs);
  const changes = new Float32Array(pairs);
  const sorted = new Float32Array(pairs);
  for (let p = 0; p < pixels; p++) {
    for (let c = 0; c < 3; c++) {
      const i = p * 3 + c;
      for (let k = 0; k < pairs; k++) changes[k] = images[k + 1][i] - images[k][i];
      sorted.set(changes);
      sorted.sort();
      const median = pairs % 2 ? sorted[pairs >> 1] : (sorted[pairs / 2 - 1] + sorted[pairs / 2]) / 2;
      for (let k = 0; k < pairs; k++) {
        const d = Math.abs(changes[k] - median);
        if (d > departures[p * pairs + k]) departures[p * pairs + k] = d;
      }
    }
  }
  return { width, height, pairs, departures };
}

/**
 * The pops of `dolly` (popDepartures) that `explaining` (the same frames' light) does not explain.
 * @returns {{ pops: number, pixels: number, largest: number, byOctave: number[] }} pixel-pairs that
 *   pop, pixels that pop at least once, the largest pop (steps), pops of [1, 2), [2, 4), [4, 8),
 *   [8, 16) and 16 or more steps
 */
export function countPops(dolly, explaining) {
  const { width, height, pairs, departures } = dolly;
  if (explaining.width !== width || explaining.height !== height || explaining.pairs !== pairs) throw new RangeError('countPops: the two dollies differ in size');
  let pops = 0;
  let largest = 0;
  const byOctave = [0, 0, 0, 0, 0];
  const popped = new Uint8Array(width * height);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const p = y * width + x;
      for (let k = 0; k < pairs; k++) {
        const d = departures[p * pairs + k];
        if (!(d >= POP_STEPS)) continue;
        let explained = false;
        for (let dy = -1; dy <= 1 && !explained; dy++) {
          for (let dx = -1; dx <= 1 && !explained; dx++) {
            const [xx, yy] = [x + dx, y + dy];
            if (xx >= 0 && yy >= 0 && xx < width && yy < height) explained = explaining.departures[(yy * width + xx) * pairs + k] >= EXPLAINED_STEPS;
          }
        }
        if (explained) continue;
        pops++;
        popped[p] = 1;
        largest = Math.max(largest, d);
        byOctave[Math.min(4, Math.floor(Math.log2(d / POP_STEPS)))]++;
      }
    }
  }
  return { pops, pixels: popped.reduce((n, v) => n + v, 0), largest, byOctave };
}
