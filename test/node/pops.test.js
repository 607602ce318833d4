// test/pages/pops.js, the count of pixels that pop in a slow dolly (test/browser/creases.test.js),
// on frames built by hand: a steady ramp does not pop, a one-frame jump does, once; a jump the
// light itself makes at the pixel or beside it explains it; a jump of less than a step is no pop.
import { describe, it, expect } from 'vitest';
import { countPops, popDepartures } from '../pages/pops.js';

const W = 5;
const H = 4;
const FRAMES = 9;

/** FRAMES frames of W × H RGB, value(frame, x, y, channel). */
const frames = (value) => Array.from({ length: FRAMES }, (_, f) => Float32Array.from({ length: W * H * 3 }, (_, i) => value(f, Math.floor(i / 3) % W, Math.floor(i / 3 / W), i % 3)));

const still = popDepartures(frames(() => 10), W, H);

describe('popDepartures and countPops', () => {
  it('a steady change of any rate, different per pixel, does not pop', () => {
    const ramp = popDepartures(frames((f, x, y, c) => 3 * f * (x + 1) - y * c * f), W, H);
    expect(Math.max(...ramp.departures)).toBeLessThan(1e-5);
    expect(countPops(ramp, still)).toEqual({ pops: 0, pixels: 0, largest: 0, byOctave: [0, 0, 0, 0, 0] });
  });

  it('a jump of 1.5 steps in one channel of one pixel between frames 4 and 5, on a ramp, pops once', () => {
    const jump = popDepartures(frames((f, x, y, c) => 0.2 * f + (x === 2 && y === 1 && c === 1 && f >= 5 ? 1.5 : 0)), W, H);
    const counted = countPops(jump, still);
    expect(counted.pops).toBe(1);
    expect(counted.pixels).toBe(1);
    expect(counted.largest).toBeCloseTo(1.5, 5);
    expect(counted.byOctave).toEqual([1, 0, 0, 0, 0]);
  });

  it('a pixel flickering by 9 steps every other frame pops in every pair, at 8-16 steps', () => {
    const flicker = popDepartures(frames((f, x, y) => (x === 0 && y === 0 && f % 2 ? 9 : 0)), W, H);
    // the median change of eight ±9 changes is 0: each departs by 9
    expect(countPops(flicker, still)).toEqual({ pops: FRAMES - 1, pixels: 1, largest: 9, byOctave: [0, 0, 0, FRAMES - 1, 0] });
  });

  it('the light jumping by half a step or more at the pixel or a neighbour in the same pair explains the pop; elsewhere or in another pair it does not', () => {
    const jump = popDepartures(frames((f, x, y) => (x === 2 && y === 1 && f >= 5 ? 4 : 0)), W, H);
    const lightJump = (lx, ly, from, size = 0.5) => popDepartures(frames((f, x, y) => (x === lx && y === ly && f >= from ? size : 0)), W, H);
    expect(countPops(jump, lightJump(2, 1, 5)).pops).toBe(0);
    expect(countPops(jump, lightJump(3, 2, 5)).pops).toBe(0); // a diagonal neighbour
    expect(countPops(jump, lightJump(4, 1, 5)).pops).toBe(1); // two pixels away
    expect(countPops(jump, lightJump(2, 1, 6)).pops).toBe(1); // another pair
    expect(countPops(jump, lightJump(2, 1, 5, 0.4)).pops).toBe(1); // less than half a step
  });

  it('a jump of less than a whole step is no pop; fewer than 3 frames or dollies of different sizes are refused', () => {
    expect(countPops(popDepartures(frames((f, x, y) => (x === 1 && y === 1 && f >= 3 ? 0.99 : 0)), W, H), still).pops).toBe(0);
    expect(() => popDepartures(frames(() => 0).slice(0, 2), W, H)).toThrow(RangeError);
    expect(() => countPops(still, popDepartures(frames(() => 0).slice(0, 5), W, H))).toThrow(RangeError);
  });
});
