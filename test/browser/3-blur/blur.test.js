// Stage 3 on the GPU: the separable, depth- and mask-aware blur, checked against the float64
// oracle and against closed-form expectations. Scenes come from test/pages/lab.js.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { evaluateFloats, openPage, runLab } from '../../harness/page.js';
import { at, channel, rgb, subtract, countNonFinite } from '../../harness/images.js';
import { separableBlurOracle, roundToHalfFloat, edgeResponse1D } from '../../oracle/convolution.js';
import { getProfile } from '../../../src/profiles/presets.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

/** The blurred diffuse light: output − light attachment, on subsurface pixels. */
function scattered(r) {
  return subtract(r.output, r.light);
}

describe('aspect fix: horizontal and vertical widths agree in world units at 16:9', () => {
  it('a blurred point spreads equally in x and y (world units), within 2 %', async () => {
    // The camera 20 units away: the kernel (35 px) stays inside the image in both directions, so no
    // tap is dropped at a border (where renormalisation would skew the moments).
    const r = await runLab(page, {
      scene: 'slab', pattern: 'point', cells: 255, width: 256, height: 144, distance: 20, widthMm: 4,
      sss: { followSurface: 'off', samples: 25 }, reads: ['output', 'light', 'diffuse', 'surface'], type: 'float',
    });
    const { width, height } = r;
    const moments = (img) => {
      let s = 0, sx = 0, sy = 0, sxx = 0, syy = 0;
      for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) {
        const v = img[at(width, x, y)]; // red: the widest channel
        s += v; sx += v * x; sy += v * y; sxx += v * x * x; syy += v * y * y;
      }
      const mx = sx / s, my = sy / s;
      return { s, varX: sxx / s - mx * mx, varY: syy / s - my * my };
    };
    const before = moments(r.diffuse);
    const after = moments(scattered(r));
    // Pixel sizes in world units at the slab's depth, per axis (aspect and fov included).
    const depth = r.surface[at(width, width >> 1, height >> 1)];
    const pxX = (2 * depth) / (r.projectionScale[0] * width);
    const pxY = (2 * depth) / (r.projectionScale[1] * height);
    const sigmaX = Math.sqrt(after.varX - before.varX) * pxX;
    const sigmaY = Math.sqrt(after.varY - before.varY) * pxY;
    expect(Math.abs(pxX / pxY - 1)).toBeLessThan(1e-3); // square pixels: the check is meaningful
    expect(sigmaX).toBeGreaterThan(0.02); // it did blur (world units)
    expect(Math.abs(sigmaX / sigmaY - 1)).toBeLessThan(0.02);
    // Energy of the point is kept.
    expect(Math.abs(after.s / before.s - 1)).toBeLessThan(0.005);
  });
});

describe('grazing angles', () => {
  // A point of light on a slab turned 60° about the vertical axis: on the surface, light must spread
  // as far across (x) as up (y); on screen the x spread is foreshortened by cos 60° = 0.5.
  // `vertical`: the slab turned about the horizontal axis instead (the y spread foreshortened).
  const spread = async (foreshortening, { vertical = false, sss = {}, samples = 0 } = {}) => {
    const r = await runLab(page, {
      scene: 'slab', pattern: 'point', cells: 255, ...(vertical ? { tiltXDeg: 60 } : { tiltDeg: 60 }), width: 256, height: 144, widthMm: 4, type: 'float', samples,
      sss: { followSurface: 'drop', samples: 25, foreshortening, ...sss }, reads: ['output', 'light', 'diffuse', 'surface'],
    });
    const { width, height } = r;
    const moments = (img) => {
      let s = 0, sx = 0, sy = 0, sxx = 0, syy = 0;
      for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) {
        const v = img[at(width, x, y)];
        s += v; sx += v * x; sy += v * y; sxx += v * x * x; syy += v * y * y;
      }
      const mx = sx / s, my = sy / s;
      return { varX: sxx / s - mx * mx, varY: syy / s - my * my, mx, my };
    };
    const before = moments(r.diffuse);
    const after = moments(scattered(r));
    const depth = r.surface[at(width, Math.round(before.mx), Math.round(before.my))];
    const pxX = (2 * depth) / (r.projectionScale[0] * width);
    const pxY = (2 * depth) / (r.projectionScale[1] * height);
    const surfaceX = (Math.sqrt(after.varX - before.varX) * pxX) / (vertical ? 1 : Math.cos(Math.PI / 3));
    const surfaceY = (Math.sqrt(after.varY - before.varY) * pxY) / (vertical ? Math.cos(Math.PI / 3) : 1);
    return vertical ? surfaceY / surfaceX : surfaceX / surfaceY;
  };

  it('the blur spreads light equally along a tilted surface (within 5 %) with the correction, and not without', async () => {
    expect(Math.abs((await spread(true)) - 1)).toBeLessThan(0.05);
    // Without it, 'drop' reads the tilted plane as a depth edge and cuts the kernel short across it.
    expect(Math.abs((await spread(false)) - 1)).toBeGreaterThan(0.4);
  });

  it("the isotropic blur with MSAA 4, turned about either axis, spreads light equally along the surface too (within 5 %)", async () => {
    // Turned about the horizontal axis, the vertical pass's own slope is the one corrected: the
    // groups' vertical pass reads the slope's coverage from the multi-target's diffuse (its light
    // comes from the group target).
    for (const vertical of [false, true]) {
      expect(Math.abs((await spread(true, { vertical, samples: 4, sss: { kernelGroups: 'auto' } })) - 1), vertical ? 'about x' : 'about y').toBeLessThan(0.05);
    }
  });
});

describe('accuracy', () => {
  it('matches the float64 oracle\'s separable result at a hard light edge within 1e-3 of the lit level (one kernel: kernelGroups 1)', async () => {
    const cases = [['edgeX', 17, 'reference'], ['edgeY', 11, 'marginal'], ['noise', 25, 'footprint'], ['edgeX', 9, 'footprint']];
    for (const [pattern, samples, method] of cases) {
      const r = await runLab(page, {
        scene: 'slab', pattern, widthMm: 2, sss: { samples, method, followSurface: 'drop', kernelGroups: 1 },
        reads: ['output', 'light', 'diffuse', 'surface'],
      });
      const { width, height } = r;
      const oracle = separableBlurOracle({
        width, height, diffuse: rgb(r.diffuse), depth: channel(r.surface, 0), widthWorld: channel(r.surface, 1),
        kernel: r.kernel, projectionScale: r.projectionScale, followSurface: 'drop',
        depthThresholdWorld: r.depthThresholdWorld, storeIntermediate: roundToHalfFloat,
        footprint: method === 'footprint' ? { ...r.footprint, profile: getProfile(r.profile) } : undefined,
        foreshorten: true,
      });
      const gpu = scattered(r);
      const lit = Math.max(...channel(r.diffuse, 0));
      let worst = 0;
      for (let i = 0; i < width * height; i++) {
        for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(gpu[i * 4 + c] - oracle[i * 3 + c]));
      }
      expect(r.blurEnabled).toBe(true);
      expect(worst / lit, `${pattern} ${method} ${samples}`).toBeLessThan(1e-3);
    }
  });

  it('the footprint-weighted marginal kernel matches the exact 2D convolution along the axes within 1 %', async () => {
    // 1 profile mm = widthWorld · P0 / (2 z) · W pixels: 0.075 · 3.19 / 20 · 320 ≈ 3.8 px per mm: red's
    // tail reaches ~55 px, which a budget of 45 taps covers with footprints of one or two pixels.
    const r = await runLab(page, {
      scene: 'slab', pattern: 'edgeX', low: 0, widthMm: 0.15, worldUnitInMm: 2, width: 320, height: 180,
      sss: { samples: 45, method: 'footprint', followSurface: 'off' }, reads: ['output', 'light', 'diffuse', 'surface'], type: 'float',
    });
    const { width, height } = r;
    const profile = getProfile('skin');
    const y = height >> 1;
    const gpu = scattered(r);
    const depth = r.surface[at(width, width >> 1, y)];
    const widthWorld = r.surface[at(width, width >> 1, y) + 1];
    const pxPerMm = (widthWorld * r.projectionScale[0] * width) / (2 * depth);
    // The edge sits where the input drops from lit to 0.
    let edge = 0;
    for (let x = 1; x < width; x++) if (r.diffuse[at(width, x - 1, y)] > 0.5 && r.diffuse[at(width, x, y)] < 0.5) edge = x;
    const lit = [0, 1, 2].map((c) => r.diffuse[at(width, edge - 40, y) + c]);
    let worst = 0;
    for (let x = edge - 30; x < edge + 30; x++) {
      // Exact: the lit half-plane convolved with the radial profile is ∫ marginal beyond the edge.
      const dMm = (x + 0.5 - edge) / pxPerMm;
      const exact = edgeResponse1D(profile, dMm);
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(gpu[at(width, x, y) + c] / lit[c] - exact[c]));
    }
    expect(pxPerMm).toBeGreaterThan(3.5);
    expect(worst).toBeLessThan(0.01);
  });
});

describe('mask: only subsurface pixels change', () => {
  it('background and ordinary materials are identical to the same scene without the pipeline', async () => {
    const common = { scene: 'mixed', widthMm: 3, type: 'float' };
    const withSss = await runLab(page, { ...common, reads: ['output', 'surface'] });
    const plain = await runLab(page, { ...common, pipeline: 'plain' });
    const { width, height } = withSss;
    let compared = 0, subsurface = 0, worst = 0;
    for (let i = 0; i < width * height; i++) {
      if (withSss.surface[i * 4 + 1] > 0) { subsurface++; continue; }
      compared++;
      for (let c = 0; c < 4; c++) worst = Math.max(worst, Math.abs(withSss.output[i * 4 + c] - plain.output[i * 4 + c]));
    }
    expect(subsurface).toBeGreaterThan(0.1 * width * height);
    expect(compared).toBeGreaterThan(0.3 * width * height);
    expect(worst).toBeLessThan(1e-4);
  });

  it('taps on ordinary pixels get zero weight: a 50× brighter neighbour changes no subsurface pixel', async () => {
    const common = { scene: 'mixed', widthMm: 6, type: 'float', reads: ['output', 'surface'] };
    const dim = await runLab(page, { ...common, brightness: 1 });
    const bright = await runLab(page, { ...common, brightness: 50 });
    const { width, height } = dim;
    let worst = 0;
    for (let i = 0; i < width * height; i++) {
      if (!(dim.surface[i * 4 + 1] > 0)) continue;
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(bright.output[i * 4 + c] - dim.output[i * 4 + c]));
    }
    expect(worst).toBeLessThan(1e-5);
  });
});

describe('depth-aware', () => {
  it('leaks across a depth edge at most 2 % of what a depth-blind blur leaks', async () => {
    const leak = async (followSurface) => {
      const r = await runLab(page, {
        scene: 'depthEdge', gapWorld: 2, widthMm: 4, sss: { followSurface, samples: 25 },
        reads: ['output', 'light', 'surface'],
      });
      const { width, height } = r;
      const s = scattered(r);
      let total = 0;
      for (let y = 10; y < height - 10; y++) {
        for (let x = 0; x < width; x++) {
          const depth = r.surface[at(width, x, y)];
          if (depth > 9) total += s[at(width, x, y)]; // far slab: depth 10; the near one is at 8
        }
      }
      const base = s[at(width, width - 5, height >> 1)]; // far slab, far from the edge
      let farPixels = 0;
      for (let y = 10; y < height - 10; y++) for (let x = 0; x < width; x++) if (r.surface[at(width, x, y)] > 9) farPixels++;
      return total - base * farPixels;
    };
    const blind = await leak('off');
    const dropped = await leak('drop');
    const lerped = await leak('lerp');
    expect(blind).toBeGreaterThan(0.5); // the depth-blind blur does bleed
    expect(Math.abs(dropped)).toBeLessThan(0.02 * blind);
    expect(Math.abs(lerped)).toBeLessThan(0.02 * blind);
  });
});

describe('energy and HDR', () => {
  it('keeps the diffuse energy of a lit slab\'s interior within 0.5 %, and blurs radiance 50 unclamped', async () => {
    const r = await runLab(page, {
      scene: 'slab', pattern: 'noise', intensity: 50 * Math.PI, widthMm: 0.5, reads: ['output', 'light', 'diffuse'],
    });
    const { width, height } = r;
    const s = scattered(r);
    const margin = 30; // wider than the kernel's radius on screen (≈ 21 px)
    let before = 0, after = 0, peak = 0;
    for (let y = margin; y < height - margin; y++) for (let x = margin; x < width - margin; x++) {
      const i = at(width, x, y);
      before += r.diffuse[i]; after += s[i];
      peak = Math.max(peak, s[i]);
    }
    expect(Math.abs(after / before - 1)).toBeLessThan(0.005);
    expect(peak).toBeGreaterThan(20);
    expect(countNonFinite(r.output)).toBe(0);
  });

  it('never lets NaN or Inf out, even from non-finite input pixels', async () => {
    const r = await runLab(page, { scene: 'slab', pattern: 'nan', widthMm: 3, reads: ['output', 'diffuse'] });
    expect(countNonFinite(r.diffuse)).toBe(0); // the material output is sanitised
    expect(countNonFinite(r.output)).toBe(0);
    const direct = await page.evaluate(async () => {
      // The blur pass on its own, fed a texture with NaN and Inf.
      const { THREE, SSS, createRenderer, dataTexture, read } = window.lab;
      const renderer = createRenderer(32, 32);
      const diffuse = dataTexture(32, 32, (x, y) => (x === 16 && y === 16 ? [NaN, Infinity, -Infinity] : [1, 1, 1]));
      const surface = dataTexture(32, 32, () => [5, 0.05, 0]);
      const camera = new THREE.PerspectiveCamera(30, 1, 0.1, 10);
      const kernel = SSS.computeKernel({ samples: 9, profile: 'skin' });
      const pass = new SSS.SubsurfaceBlurPass({ direction: 'horizontal', kernel, camera, surfaceTexture: surface, diffuseTexture: diffuse });
      pass.setSize(32, 32);
      const target = new THREE.WebGLRenderTarget(32, 32, { type: THREE.FloatType });
      pass.render(renderer, target, null);
      const data = await read(renderer, target);
      let bad = 0;
      for (const v of data) if (!Number.isFinite(v)) bad++;
      pass.dispose(); target.dispose(); renderer.dispose();
      return bad;
    });
    expect(direct).toBe(0);
  });
});

describe('strength', () => {
  it('widthScale 0 on a material turns scattering off and keeps its diffuse light', async () => {
    const common = { scene: 'slab', pattern: 'noise', type: 'float', widthMm: 2 };
    const off = await runLab(page, { ...common, material: { widthScale: 0 }, reads: ['output'] });
    const plain = await runLab(page, { ...common, pipeline: 'plain' });
    let worst = 0;
    for (let i = 0; i < off.output.length; i++) worst = Math.max(worst, Math.abs(off.output[i] - plain.output[i]));
    expect(worst).toBeLessThan(1e-5);
  });

  it('RGB strength mixes the footprint blur with no scattering, per channel (float precision: one kernel, kernelGroups 1; the groups carry halves)', async () => {
    const common = { scene: 'slab', pattern: 'edgeX', type: 'float', widthMm: 2, reads: ['output', 'light', 'diffuse'] };
    const full = await runLab(page, { ...common, sss: { strength: [1, 1, 1], kernelGroups: 1 } });
    const mixed = await runLab(page, { ...common, sss: { strength: [0, 0.5, 1], kernelGroups: 1 } });
    let worst = [0, 0, 0];
    let moved = 0;
    for (let i = 0; i < full.output.length; i += 4) {
      for (let c = 0; c < 3; c++) {
        const raw = full.diffuse[i + c];
        const blurred = full.output[i + c] - full.light[i + c];
        const expected = raw + (blurred - raw) * [0, 0.5, 1][c];
        worst[c] = Math.max(worst[c], Math.abs(mixed.output[i + c] - mixed.light[i + c] - expected));
        if (c === 2) moved = Math.max(moved, Math.abs(blurred - raw));
      }
    }
    expect(moved).toBeGreaterThan(0.05); // the edge is blurred at strength 1
    // Each pass mixes its result with its input by s; on an edge along x the vertical pass finds
    // nothing to blur, so the output is raw + s · (fully blurred − raw) exactly, per channel.
    for (let c = 0; c < 3; c++) expect(worst[c], `channel ${c}`).toBeLessThan(1e-5);
  });
});

describe('below one pixel, no work', () => {
  it('skips both blurs and equals the no-SSS output when the kernel is under half a pixel', async () => {
    const common = { scene: 'slab', pattern: 'noise', type: 'float' };
    const tiny = await runLab(page, { ...common, widthMm: 0.001, reads: ['output'] });
    const plain = await runLab(page, { ...common, pipeline: 'plain' });
    expect(tiny.kernelPixels).toBeLessThan(0.5);
    expect(tiny.blurEnabled).toBe(false);
    let worst = 0;
    for (let i = 0; i < tiny.output.length; i++) worst = Math.max(worst, Math.abs(tiny.output[i] - plain.output[i]));
    expect(worst).toBeLessThan(1e-5);
    const wide = await runLab(page, { ...common, widthMm: 1, reads: ['output'] });
    expect(wide.kernelPixels).toBeGreaterThan(0.5);
    expect(wide.blurEnabled).toBe(true);
  });
});

describe('the depth carried in the light (one fetch per tap)', () => {
  // The diffuse attachment and the horizontal blur's output carry the linear view depth in their
  // alpha; off the mask the alpha is 0, and a depth of exactly 0 is written as 1e-30
  // (shaders/common/carriedDepth.glsl). An orthographic camera sees a plane on its own plane (depth
  // 0) and behind it (negative depths): the blur must not take either for off the mask. With an
  // orthographic camera the scale does not depend on depth, so each frame must equal the one with
  // the plane in front, to the bit.
  it('a plane at depth 0 and behind an orthographic camera blurs exactly as in front of it', async () => {
    const r = await page.evaluate(async () => {
      const { SSS, createRenderer, createComposer, flatScene, read } = window.lab;
      const width = 160, height = 90;
      const renderer = createRenderer(width, height);
      const built = flatScene({ width, height, pxPerMm: 4, pattern: 'step' });
      const frame = async (cameraZ, near) => {
        Object.assign(built.camera, { near, far: 1000 });
        built.camera.position.z = cameraZ;
        built.camera.updateProjectionMatrix();
        built.camera.updateMatrixWorld();
        const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: 1, type: window.lab.THREE.FloatType });
        sss.makeSubsurface(built.material, { widthMm: 1 });
        const composer = createComposer(renderer, { type: window.lab.THREE.FloatType });
        composer.addPass(sss);
        composer.render();
        const out = {
          scattered: Array.from(await read(renderer, sss._blur.scatteredTarget)),
          depthAlpha: (await read(renderer, sss._scenePass.renderTarget, 1))[((height >> 1) * width + (width >> 1)) * 4 + 3],
          horizontalAlpha: (await read(renderer, sss._blur._blurTarget))[((height >> 1) * width + (width >> 1)) * 4 + 3],
          carries: sss._scenePass.diffuseCarriesDepth,
          blur: sss.plan.blur,
        };
        sss.dispose();
        composer.dispose();
        return out;
      };
      const front = await frame(100, 1);
      const onPlane = await frame(0, -10);
      const behind = await frame(-50, -100);
      renderer.dispose();
      return { width, height, front, onPlane, behind };
    });
    expect(r.front.blur && r.front.carries).toBe(true);
    expect(r.front.depthAlpha).toBeCloseTo(100, 4);
    // Depth 0 is carried as 1e-30 in the diffuse attachment and in the horizontal blur's output.
    for (const alpha of [r.onPlane.depthAlpha, r.onPlane.horizontalAlpha]) expect(alpha / 1e-30).toBeCloseTo(1, 5);
    expect(r.front.horizontalAlpha).toBeCloseTo(100, 4);
    expect(r.behind.depthAlpha).toBeCloseTo(-50, 4);
    // The edge did blur: across it the scattered light runs between the two levels.
    const row = (img) => Array.from({ length: r.width }, (_, x) => img[((r.height >> 1) * r.width + x) * 4]);
    const middle = row(r.front.scattered);
    expect(middle.filter((v) => v > 0.1 && v < 0.9).length).toBeGreaterThan(2);
    let worstOnPlane = 0, worstBehind = 0;
    for (let i = 0; i < r.front.scattered.length; i++) {
      worstOnPlane = Math.max(worstOnPlane, Math.abs(r.onPlane.scattered[i] - r.front.scattered[i]));
      worstBehind = Math.max(worstBehind, Math.abs(r.behind.scattered[i] - r.front.scattered[i]));
    }
    expect(worstOnPlane).toBe(0);
    expect(worstBehind).toBe(0);
  });
});

describe('an ArrayCamera (issue 40)', () => {
  it("blurs each view at its own camera's scale: each view is the frame of a pipeline drawn with that camera alone, a view fading in and one not blurred too", async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, EffectComposer, createRenderer, read, buildScene, DEFAULTS } = window.lab;
      const [w, h] = [64, 72];
      const renderer = createRenderer(w, h);
      const built = buildScene('slab', { pattern: 'noise', slabSize: 3 });
      const options = { scene: built.scene, worldUnitInMm: DEFAULTS.worldUnitInMm, type: THREE.FloatType };
      const frame = async (camera, width, height) => {
        renderer.setSize(width, height, false);
        const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType }));
        composer.renderToScreen = false;
        const sss = new SSS.SubsurfaceScattering({ ...options, camera });
        sss.makeSubsurface(built.subsurface[0], { widthMm: 1 });
        composer.addPass(sss);
        composer.render();
        const out = { image: await read(renderer, composer.readBuffer), plan: { ...sss.plan }, problems: [...sss.problems] };
        sss.dispose();
        composer.dispose();
        return out;
      };
      const view = (fov, distance) => {
        const camera = new THREE.PerspectiveCamera(fov, w / h, 0.1, 10000);
        camera.position.set(0, 0, distance);
        camera.lookAt(0, 0, 0);
        camera.updateMatrixWorld();
        return camera;
      };
      // A view whose blur fades in (between half a pixel and one of reach): the first such distance.
      let fading = null;
      for (let distance = 60; distance < 400 && !fading; distance *= 1.15) {
        const { plan } = await frame(view(20, distance), w, h);
        if (plan.blur && plan.fade > 0.1 && plan.fade < 0.9) fading = distance;
      }
      const cameras = [view(20, 10), view(40, 10), view(20, fading), view(20, fading * 2)]; // the last: no blur
      cameras.forEach((camera, i) => { camera.viewport = new THREE.Vector4(i * w, 0, w, h); });
      const array = new THREE.ArrayCamera(cameras); // the container left at fov 50, as three's example does
      array.position.set(0, 0, 10);
      array.updateMatrixWorld();
      const whole = await frame(array, cameras.length * w, h);
      const alone = [];
      for (const camera of cameras) alone.push(await frame(camera, w, h));
      return { whole: whole.image, problems: whole.problems, alone: alone.map((a) => ({ image: a.image, plan: a.plan })), w, h, count: cameras.length, fading };
    });
    const { w, h, count } = r;
    expect(r.fading).not.toBe(null);
    expect(r.alone.map(({ plan }) => [plan.blur, plan.fade === 1])).toEqual([[true, true], [true, true], [true, false], [false, false]]);
    expect(r.problems).toEqual([]);
    for (let k = 0; k < count; k++) {
      const alone = r.alone[k].image;
      let worst = 0;
      let wrong = 0;
      let lit = 0;
      for (let y = 0; y < h; y++) {
        for (let x = 0; x < w; x++) {
          for (let c = 0; c < 3; c++) {
            const a = alone[(y * w + x) * 4 + c];
            const b = r.whole[(y * w * count + k * w + x) * 4 + c];
            lit = Math.max(lit, a);
            worst = Math.max(worst, Math.abs(a - b));
            if (Math.abs(a - b) > 1e-3) wrong++;
          }
        }
      }
      expect(lit, `view ${k}`).toBeGreaterThan(0.1);
      expect(worst, `view ${k}: ${wrong} channel values off by more than 1e-3`).toBeLessThan(1e-5 * lit);
    }
  });
});
