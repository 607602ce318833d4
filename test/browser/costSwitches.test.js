// Issue 19's savings and their switches (the bench undoes each for one measure): the scene split
// without the depth prepass (each subsurface object rasterised once), the blur scissored to the
// subsurface pixels' screen box, the compose fetching less, the light depth pass skipped while
// unread, the blur fetching only the texels its taps weigh, the depth carried in the diffuse
// attachment and handed between the blur passes in the light, the compose's mask from the scattered
// light, and with MSAA the depth resolved once. Each switch must leave the image as it is: every variant is held against the frame with
// every saving on, float read-backs, and the ordinary pixels against a plain three.js frame (the
// shadows cast by and onto subsurface objects kept).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats, closeCheckedPage } from '../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(() => closeCheckedPage(page));

/**
 * In the page: a subsurface sphere (noise albedo) over an ordinary floor, a second subsurface
 * sphere half hidden behind it, an ordinary box in front of both; a directional light casting
 * shadows. Renders it through the pipeline once per variant (switches set on a fresh pipeline;
 * `moved`: one frame with the spheres elsewhere first, so the box moves between frames) and once
 * with a plain RenderPass; reads the outputs, the scattered light and the diffuse attachment.
 */
function renderVariants(variants) {
  const { THREE, SSS, RenderPass, createRenderer, createComposer, read, dataTexture } = window.lab;
  const width = 192, height = 108;
  const renderer = createRenderer(width, height);
  renderer.shadowMap.enabled = true;
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(30, width / height, 0.5, 50);
  camera.position.set(0, 0.6, 8);
  camera.lookAt(0, 0, 0);
  let seed = 7;
  const noise = () => ((seed = (seed * 16807) % 2147483647) / 2147483647);
  const map = dataTexture(32, 32, () => { const v = 0.1 + 0.9 * noise(); return [v, 0.8 * v, 0.6 * v]; });
  const skin = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.6, map });
  const skinBehind = new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.8 });
  const front = new THREE.Mesh(new THREE.SphereGeometry(0.9, 48, 32), skin);
  const behind = new THREE.Mesh(new THREE.SphereGeometry(0.7, 32, 24), skinBehind);
  behind.position.set(0.9, 0.3, -1.2);
  const box = new THREE.Mesh(new THREE.BoxGeometry(0.5, 0.5, 0.5), new THREE.MeshStandardMaterial({ color: 0x3366cc }));
  box.position.set(-0.7, -0.3, 1.2);
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(12, 12), new THREE.MeshStandardMaterial({ color: 0x999999 }));
  floor.rotation.x = -Math.PI / 2;
  floor.position.y = -1;
  for (const m of [front, behind, box]) m.castShadow = m.receiveShadow = true;
  floor.receiveShadow = true;
  const light = new THREE.DirectionalLight(0xffffff, 3);
  light.position.set(-3, 5, 4);
  light.castShadow = true;
  Object.assign(light.shadow.camera, { left: -4, right: 4, top: 4, bottom: -4, near: 0.5, far: 20 });
  scene.add(front, behind, box, floor, light, light.target, new THREE.AmbientLight(0xffffff, 0.2));
  const subsurface = [front, behind];
  const home = subsurface.map((m) => m.position.clone());

  // A transparent pane between the spheres (the MSAA variants but one): drawn after the compose and
  // depth-tested against the scene's resolved depth, it shows whether that depth is right.
  const pane = new THREE.Mesh(new THREE.PlaneGeometry(3, 1.2), new THREE.MeshBasicMaterial({ color: 0x44ff88, transparent: true, opacity: 0.5 }));
  pane.position.set(0.4, 0.2, -0.5);

  const frame = async ({ switches = {}, moved = false, multisampling = 0, withPane = multisampling > 0 }) => {
    const composer = createComposer(renderer, { type: THREE.FloatType });
    if (withPane) scene.add(pane);
    const sss = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: 100, type: THREE.FloatType, light, multisampling });
    for (const m of [skin, skinBehind]) sss.makeSubsurface(m);
    composer.addPass(sss);
    const targets = { scene: sss._scenePass, blur: sss._blur, compose: sss._composePass, pipeline: sss };
    for (const [key, value] of Object.entries(switches)) {
      const [owner, field] = key.split('.');
      targets[owner][field] = value;
    }
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
      // The groups' programs (both passes) as compiled: whether they carry the depth.
      groupsCarry: [sss._blur.horizontalPass, sss._blur.verticalPass].flatMap((pass) => [...pass._groupMaterials.values()].map((m) => m.defines.SSS_GROUPS_CARRY_DEPTH)),
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
  saving: {},
  depthPrepass: { switches: { 'scene.depthPrepass': true } },
  fullFrameBlur: { switches: { 'blur.confineToSubsurface': false } },
  composeAsBefore: { switches: { 'compose.fetchesEverywhere': true } },
  lightDepthEveryFrame: { switches: { 'pipeline.skipsUnreadLightDepth': false } },
  bothTexelsFetched: { switches: { 'blur.skipsEmptyTexels': false } },
  depthFromSurface: { switches: { 'blur.lightCarriesDepth': false } },
  maskInDiffuse: { switches: { 'scene.diffuseCarriesDepth': false } },
  neitherCarriesDepth: { switches: { 'scene.diffuseCarriesDepth': false, 'blur.lightCarriesDepth': false } },
  maskFromDiffuse: { switches: { 'compose.maskFromScattered': false } },
  moved: { moved: true },
  // With MSAA 4, against the MSAA frame with every saving.
  msaa: { multisampling: 4, base: true },
  msaaWithoutPane: { multisampling: 4, withPane: false, base: true },
  msaaDepthResolvedTwice: { multisampling: 4, switches: { 'scene.resolvesDepthOnce': false } },
  // Premultiplied between the passes, as before: (light × coverage) / coverage is the light to
  // about an ulp, not exactly (ROUNDED).
  msaaDepthFromSurface: { multisampling: 4, switches: { 'blur.lightCarriesDepth': false }, rounded: true },
  msaaMaskFromDiffuse: { multisampling: 4, switches: { 'compose.maskFromScattered': false } },
  // The isotropic blur (four groups), against its own frame: the groups' depth from the surface.
  isotropic: { switches: { 'pipeline.kernelGroups': 4 }, base: true },
  isotropicDepthFromSurface: { switches: { 'pipeline.kernelGroups': 4, 'blur.groupsCarryDepth': false }, against: 'isotropic' },
  msaaIsotropic: { multisampling: 4, switches: { 'pipeline.kernelGroups': 4 }, base: true },
  msaaIsotropicDepthFromSurface: { multisampling: 4, switches: { 'pipeline.kernelGroups': 4, 'blur.groupsCarryDepth': false }, against: 'msaaIsotropic' },
};
/** What a rounded variant may differ by, relative to the lit level (float32: a few ulps). */
const ROUNDED = 1e-6;
/** The frame a variant is held against: the MSAA one with every saving for MSAA variants. */
const baseOf = (name) => VARIANTS[name].against ?? (VARIANTS[name].multisampling > 0 ? 'msaa' : 'saving');

const maxDifference = (a, b) => {
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
};

describe('issue 19: each saving leaves the image as it is', () => {
  let r;
  beforeAll(async () => { r = await evaluateFloats(page, renderVariants, VARIANTS); });

  it('the scene has what the savings are about: a box smaller than the frame, blur on, no GL error', () => {
    expect(r.glError).toBe(0);
    expect(r.saving.blur).toBe(true);
    const { box } = r.saving;
    expect(box).not.toBeNull(); // null would mean the whole frame: the scissor would not be tested
    expect(box.width * box.height).toBeLessThan(0.6 * r.width * r.height);
    expect(box.width * box.height).toBeGreaterThan(0.05 * r.width * r.height);
    // Every subsurface pixel (diffuse alpha > 0) lies inside the box.
    for (let y = 0; y < r.height; y++) for (let x = 0; x < r.width; x++) {
      if (!(r.saving.diffuse[(y * r.width + x) * 4 + 3] > 0)) continue;
      expect(x >= box.x && x < box.x + box.width && y >= box.y && y < box.y + box.height).toBe(true);
    }
  });

  it.each(Object.keys(VARIANTS).filter((k) => k !== 'saving' && !VARIANTS[k].base))('%s: the output and the scattered light as with every saving', (name) => {
    // The same shaders on the same inputs: the same floats (a scissor or a depth prepass changes
    // which fragments run, not what they compute).
    const base = r[baseOf(name)];
    const tolerance = VARIANTS[name].rounded ? ROUNDED * Math.max(...base.scattered) : 0;
    expect(maxDifference(r[name].output, base.output)).toBeLessThanOrEqual(tolerance);
    expect(maxDifference(r[name].scattered, base.scattered)).toBeLessThanOrEqual(tolerance);
    if (VARIANTS[name].rounded) expect(Math.max(...base.scattered)).toBeGreaterThan(0.05); // lit: the tolerance is not 0 by accident
  });

  it('the isotropic variants blur in four groups (what groupsCarryDepth is about), and differ from one kernel', () => {
    for (const name of ['isotropic', 'isotropicDepthFromSurface', 'msaaIsotropic', 'msaaIsotropicDepthFromSurface']) expect(r[name].groups, name).toBe(4);
    // The switch reaches the groups' own programs, which are what the comparison is about (with
    // MSAA the shader ignores it: the coverage is needed there, and the variant checks that).
    expect(r.isotropic.groupsCarry.length).toBeGreaterThanOrEqual(2);
    expect(r.isotropic.groupsCarry.every((v) => v === 1)).toBe(true);
    expect(r.isotropicDepthFromSurface.groupsCarry.every((v) => v === 0)).toBe(true);
    expect(r.saving.groups).toBe(1);
    expect(maxDifference(r.isotropic.scattered, r.saving.scattered)).toBeGreaterThan(1e-3);
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

  it('without the depth prepass, ordinary pixels are the plain three.js frame (shadows cast by the subsurface spheres kept)', () => {
    const { output, diffuse } = r.saving;
    let ordinary = 0, worst = 0, shadowed = 0;
    for (let i = 0; i < output.length; i += 4) {
      if (diffuse[i + 3] > 0) continue;
      ordinary++;
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(output[i + c] - r.plain[i + c]) / Math.max(r.plain[i + c], 1e-3));
      if (r.plain[i] > 0 && r.plain[i] < 0.5 * r.plain[(5 * r.width + 5) * 4]) shadowed++; // floor darker than near the corner (lit)
    }
    expect(ordinary).toBeGreaterThan(1000);
    expect(shadowed).toBeGreaterThan(50); // the spheres' shadow is on the floor
    expect(worst).toBeLessThan(1e-5); // float targets: the same shading
  });
});
