// The pipeline's frame against itself and against a plain three.js frame, on a scene with what
// the shipped savings are about (a subsurface box smaller than the frame, one subsurface sphere half
// hidden by another, shadows cast by and onto them, MSAA, a transparent pane): the ordinary pixels
// are three's, the box moving between frames leaves the same floats, and with MSAA the resolved
// depth is the scene's. Float read-backs.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats, closeCheckedPage } from '../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(() => closeCheckedPage(page));

/**
 * In the page: a subsurface sphere (noise albedo) over an ordinary floor, a second subsurface
 * sphere half hidden behind it, an ordinary box in front of both; a directional light casting
 * shadows. Renders it through the pipeline once per variant (a fresh pipeline; `settings` assigned
 * to it; `moved`: one frame with the spheres elsewhere first, so the box moves between frames) and once
 * with a plain RenderPass; reads the outputs, the scattered light and the diffuse attachment.
 */
function renderVariants(variants) {
  const { THREE, SSS, RenderPass, createRenderer, createComposer, read, spheresScene } = window.lab;
  const width = 192, height = 108;
  const renderer = createRenderer(width, height);
  renderer.shadowMap.enabled = true;
  const { scene, camera, light, skin, skinBehind, subsurface } = spheresScene(width / height);
  const home = subsurface.map((m) => m.position.clone());

  // A transparent pane between the spheres (the MSAA variants but one): drawn after the compose and
  // depth-tested against the scene's resolved depth, it shows whether that depth is right.
  const pane = new THREE.Mesh(new THREE.PlaneGeometry(3, 1.2), new THREE.MeshBasicMaterial({ color: 0x44ff88, transparent: true, opacity: 0.5 }));
  pane.position.set(0.4, 0.2, -0.5);

  const frame = async ({ settings = {}, moved = false, multisampling = 0, withPane = multisampling > 0 }) => {
    const composer = createComposer(renderer, { type: THREE.FloatType });
    if (withPane) scene.add(pane);
    const sss = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: 100, type: THREE.FloatType, light, multisampling });
    for (const m of [skin, skinBehind]) sss.makeSubsurface(m);
    composer.addPass(sss);
    Object.assign(sss, settings);
    if (moved) {
      subsurface.forEach((m) => m.position.x += 1.5);
      composer.render();
      subsurface.forEach((m, i) => m.position.copy(home[i]));
    }
    composer.render();
    const out = {
      output: await read(renderer, composer.readBuffer),
      scattered: await read(renderer, sss._blur.scatteredTarget),
      diffuse: await read(renderer, sss._scenePass.renderTarget, 1),
      box: sss._scenePass.subsurfaceBox,
      blur: sss.plan.blur,
      groups: sss.plan.groups,
    };
    sss.dispose();
    composer.dispose();
    scene.remove(pane);
    return out;
  };
  const plainFrame = async () => {
    const composer = createComposer(renderer, { type: THREE.FloatType });
    composer.addPass(new RenderPass(scene, camera));
    composer.render();
    const output = await read(renderer, composer.readBuffer);
    composer.dispose();
    return output;
  };
  return (async () => {
    const results = {};
    for (const [name, variant] of Object.entries(variants)) results[name] = await frame(variant);
    results.plain = await plainFrame();
    results.glError = renderer.getContext().getError();
    renderer.dispose();
    renderer.forceContextLoss();
    return { width, height, ...results };
  })();
}

const VARIANTS = {
  base: {},
  moved: { moved: true },
  // With MSAA 4 (and the pane, but for one).
  msaa: { multisampling: 4 },
  msaaWithoutPane: { multisampling: 4, withPane: false },
  msaaMoved: { multisampling: 4, moved: true },
  // The isotropic blur (four groups).
  isotropic: { settings: { kernelGroups: 4 } },
  isotropicMoved: { settings: { kernelGroups: 4 }, moved: true },
  msaaIsotropic: { multisampling: 4, settings: { kernelGroups: 4 } },
};

const maxDifference = (a, b) => {
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
};

describe('the pipeline frame: its box, and its ordinary pixels as three draws them', () => {
  let r;
  beforeAll(async () => { r = await evaluateFloats(page, renderVariants, VARIANTS); });

  it('the scene has what the savings are about: a box smaller than the frame, blur on, no GL error', () => {
    expect(r.glError).toBe(0);
    expect(r.base.blur).toBe(true);
    const { box } = r.base;
    expect(box).not.toBeNull(); // null would mean the whole frame: the scissor would not be tested
    expect(box.width * box.height).toBeLessThan(0.6 * r.width * r.height);
    expect(box.width * box.height).toBeGreaterThan(0.05 * r.width * r.height);
    // Every subsurface pixel (diffuse alpha not 0) lies inside the box.
    for (let y = 0; y < r.height; y++) for (let x = 0; x < r.width; x++) {
      if (r.base.diffuse[(y * r.width + x) * 4 + 3] === 0) continue;
      expect(x >= box.x && x < box.x + box.width && y >= box.y && y < box.y + box.height).toBe(true);
    }
  });

  it.each([['moved', 'base'], ['msaaMoved', 'msaa'], ['isotropicMoved', 'isotropic']])('%s: a box that moved between frames leaves the floats of %s', (name, base) => {
    // The scissor's clears when the box moves: the same shaders on the same inputs, the same floats.
    expect(maxDifference(r[name].output, r[base].output)).toBe(0);
    expect(maxDifference(r[name].scattered, r[base].scattered)).toBe(0);
  });

  it('the isotropic frames blur in four groups, and differ from one kernel', () => {
    for (const name of ['isotropic', 'msaaIsotropic']) expect(r[name].groups, name).toBe(4);
    expect(r.base.groups).toBe(1);
    expect(maxDifference(r.isotropic.scattered, r.base.scattered)).toBeGreaterThan(1e-3);
  });

  it('with MSAA, the transparent pane is hidden behind the front sphere and seen over the floor (the depth resolved once is the scene\'s)', () => {
    const { output, diffuse } = r.msaa;
    const { output: without } = r.msaaWithoutPane;
    let frontUnchanged = 0, front = 0, paneSeen = 0;
    for (let i = 0; i < output.length; i += 4) {
      const green = output[i + 1] - without[i + 1];
      const x = (i / 4) % r.width;
      if (diffuse[i + 3] > 0 && x < r.width / 2) { // the front sphere's left half: in front of the pane
        front++;
        if (Math.abs(green) < 0.05 * Math.max(without[i + 1], 0.05)) frontUnchanged++;
      } else if (diffuse[i + 3] === 0 && green > 0.1) paneSeen++;
    }
    expect(paneSeen).toBeGreaterThan(200);
    expect(front).toBeGreaterThan(200);
    expect(frontUnchanged / front).toBeGreaterThan(0.97); // antialiased rims aside
  });

  it('ordinary pixels are the plain three.js frame (each subsurface object drawn once, shadows cast by the subsurface spheres kept)', () => {
    const { output, diffuse } = r.base;
    let ordinary = 0, worst = 0, shadowed = 0;
    for (let i = 0; i < output.length; i += 4) {
      if (diffuse[i + 3] !== 0) continue;
      ordinary++;
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(output[i + c] - r.plain[i + c]) / Math.max(r.plain[i + c], 1e-3));
      if (r.plain[i] > 0 && r.plain[i] < 0.5 * r.plain[(5 * r.width + 5) * 4]) shadowed++; // floor darker than near the corner (lit)
    }
    expect(ordinary).toBeGreaterThan(1000);
    expect(shadowed).toBeGreaterThan(50); // the spheres' shadow is on the floor
    expect(worst).toBeLessThan(1e-5); // float targets: the same shading
  });
});
