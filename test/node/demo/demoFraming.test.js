// The demo's camera shots: the full head at 16:9 is the bench's and figures' default camera, and a
// narrower window backs the camera off along the same line until the shot's width fits.
import { describe, it, expect } from 'vitest';
import { SHOTS, shotCamera } from '../../../demo/framing.js';
import { DEFAULT_CAMERA } from '../../../demo/headScene.js';
import { defaultState } from '../../../demo/state.js';

const FOV = 25; // the demo camera's vertical field of view

describe('demo camera shots', () => {
  it('the page opens on the face close-up, split in two', () => {
    expect(defaultState()).toMatchObject({ shot: 'face', camera: null, split: 0.5 });
  });

  it('at 16:9 each shot is its reference camera; the full head is DEFAULT_CAMERA', () => {
    for (const name of Object.keys(SHOTS)) {
      shotCamera(name, 16 / 9, FOV).forEach((v, i) => expect(v).toBeCloseTo(SHOTS[name].camera[i], 10));
    }
    shotCamera('head', 16 / 9, FOV).forEach((v, i) => expect(v).toBeCloseTo(DEFAULT_CAMERA[i], 10));
  });

  it('in a portrait window the camera backs off along the same line until halfWidth fits', () => {
    for (const aspect of [1, 0.5, 400 / 760]) {
      for (const name of Object.keys(SHOTS)) {
        const [x, y, z, tx, ty, tz] = shotCamera(name, aspect, FOV);
        const ref = SHOTS[name].camera;
        expect([tx, ty, tz]).toEqual(ref.slice(3));
        const d = Math.hypot(x - tx, y - ty, z - tz);
        const dRef = Math.hypot(ref[0] - ref[3], ref[1] - ref[4], ref[2] - ref[5]);
        // Same direction, never closer than the reference.
        const dir = [(x - tx) / d, (y - ty) / d, (z - tz) / d];
        const dirRef = [(ref[0] - ref[3]) / dRef, (ref[1] - ref[4]) / dRef, (ref[2] - ref[5]) / dRef];
        dir.forEach((v, i) => expect(v).toBeCloseTo(dirRef[i], 10));
        expect(d).toBeGreaterThanOrEqual(dRef - 1e-9);
        // The visible half-width at the target is at least halfWidth.
        const halfWidth = d * Math.tan((FOV * Math.PI) / 360) * aspect;
        expect(halfWidth).toBeGreaterThanOrEqual(SHOTS[name].halfWidth - 1e-9);
      }
    }
  });

  it('refuses an unknown shot', () => {
    expect(() => shotCamera('ear', 1, FOV)).toThrow(/face, head/);
  });
});
