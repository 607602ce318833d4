// What a user meets the day they adopt or upgrade (issue 22), against plain three.js as the oracle:
// a subsurface material drawn outside any pipeline is three's own; the transparent-material
// warning names what the user named; a pipeline disabled with nothing else drawing its scene says
// the frame is frozen (0.1's `enabled = false` turned the blur off); renderer.setEffects([sss])
// draws the composer path's pixels without the renderer's own draw of the scene.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openLabPage, closeCheckedPage, evaluateFloats } from '../harness/page.js';

let page;
const warnings = [];
beforeAll(async () => { page = await openLabPage(warnings); });
afterAll(() => closeCheckedPage(page));

/** Largest |a − b| over RGB, and the fraction of pixels differing by more than `tolerance`. */
function compare(a, b, tolerance) {
  let worst = 0;
  let differing = 0;
  for (let i = 0; i < a.length / 4; i++) {
    let d = 0;
    for (let c = 0; c < 3; c++) d = Math.max(d, Math.abs(a[i * 4 + c] - b[i * 4 + c]));
    worst = Math.max(worst, d);
    if (d > tolerance) differing++;
  }
  return { worst, differing: differing / (a.length / 4) };
}

describe('a subsurface material outside the pipeline', () => {
  it("draws exactly three's own material in a plain RenderPass and in a direct render, after the pipeline drew it with transmittance", async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('backlit', { thicknessMm: 2, slabSize: 2 });
      built.scene.add(new THREE.HemisphereLight(0xffffff, 0x332222, 1)); // the front is lit too
      const material = built.subsurface[0];
      const plain = createComposer(renderer);
      plain.addPass(new RenderPass(built.scene, built.camera));
      const minimap = new THREE.WebGLRenderTarget(DEFAULTS.width, DEFAULTS.height, { type: THREE.HalfFloatType });
      const drawPlain = async () => {
        plain.render();
        renderer.setRenderTarget(minimap);
        renderer.render(built.scene, built.camera);
        renderer.setRenderTarget(null);
        return { pass: await read(renderer, plain.readBuffer), direct: await read(renderer, minimap) };
      };
      const threeOwn = await drawPlain(); // before the material is made subsurface

      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(material, { widthMm: 1 });
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.render();
      const pipeline = await read(renderer, composer.readBuffer);
      sss.debugView = 'transmittance';
      composer.render();
      const transmitted = await read(renderer, composer.readBuffer);
      sss.debugView = 'final';
      composer.render(); // the pipeline's settings are the material's last ones, light included
      const outside = await drawPlain();
      const hooked = material.customProgramCacheKey().includes('subsurface');
      sss.dispose();
      composer.dispose();
      plain.dispose();
      minimap.dispose();
      return { threeOwn, outside, pipeline, transmitted, hooked, glError: renderer.getContext().getError() };
    });
    expect(r.glError).toBe(0);
    expect(r.hooked).toBe(true); // the plain draws went through the hooked shader
    // The light does come through here: the pipeline adds it over most of the slab.
    let lit = 0;
    for (let i = 0; i < r.transmitted.length / 4; i++) if (r.transmitted[i * 4] > 1e-3) lit++;
    expect(lit / (r.transmitted.length / 4)).toBeGreaterThan(0.1);
    expect(compare(r.pipeline, r.threeOwn.pass, 1e-3).differing).toBeGreaterThan(0.1);
    // Outside the pipeline: three's own pixels (the latest pipeline's transmittance was added before).
    for (const path of ['pass', 'direct']) {
      const { worst, differing } = compare(r.outside[path], r.threeOwn[path], 1e-4);
      expect(differing, path).toBe(0);
      expect(worst, path).toBeLessThan(1e-4);
    }
  });
});

describe('messages name what the user named', () => {
  it("the transparent-material warning names an unnamed material by its type and its mesh's name, never by its uuid", async () => {
    warnings.length = 0;
    const r = await page.evaluate(() => {
      const { THREE, SSS, createRenderer, createComposer, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const built = buildScene('slab', { aspect: 64 / 36 });
      const material = built.subsurface[0];
      material.transparent = true;
      built.scene.children[0].name = 'ear';
      const other = new THREE.MeshPhysicalMaterial({ transparent: true, opacity: 0.5 });
      built.scene.add(new THREE.Mesh(new THREE.PlaneGeometry(0.2, 0.2), other)); // an unnamed mesh
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(material);
      sss.makeSubsurface(other);
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.render();
      composer.render();
      sss.dispose();
      composer.dispose();
      return { uuids: [material.uuid, other.uuid] };
    });
    const transparent = warnings.filter((w) => w.includes('is transparent'));
    expect(transparent).toHaveLength(2);
    expect(transparent[0]).toMatch(/^SubsurfaceScattering: the MeshStandardMaterial of mesh "ear" is transparent, so it is blended/);
    expect(transparent[1]).toMatch(/^SubsurfaceScattering: an unnamed MeshPhysicalMaterial of an unnamed Mesh is transparent/);
    for (const uuid of r.uuids) expect(warnings.join('\n')).not.toContain(uuid);
  });
});

describe('upgrading from 0.1: enabled = false', () => {
  it('disabled with nothing else drawing its scene, the pipeline warns once that the frame is frozen; with a RenderPass in its place it says nothing', async () => {
    const frozenWarnings = () => warnings.filter((w) => w.includes('enabled is false and nothing else draws its scene'));
    warnings.length = 0;
    // 1. A RenderPass takes over, before or after it in the composer: the scene is drawn, nothing to say.
    await page.evaluate(() => {
      const { SSS, createRenderer, createComposer, buildScene, RenderPass, OutputPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const built = buildScene('slab', { pattern: 'noise', aspect: 64 / 36 });
      for (const order of ['before', 'after']) {
        const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
        sss.makeSubsurface(built.subsurface[0]);
        const renderPass = new RenderPass(built.scene, built.camera);
        renderPass.enabled = false;
        const composer = createComposer(renderer);
        for (const pass of order === 'before' ? [renderPass, sss] : [sss, renderPass]) composer.addPass(pass);
        composer.addPass(new OutputPass());
        composer.render();
        sss.enabled = false;
        renderPass.enabled = true;
        for (let i = 0; i < 8; i++) {
          composer.render();
          if (sss.enabled || sss.enabled) throw new Error('enabled'); // the user reads it too
        }
        sss.dispose();
        composer.dispose();
      }
    });
    expect(frozenWarnings()).toEqual([]);
    // 2. Disabled, with only an overlay of another scene after it: the composer's buffer keeps the
    //    last frame while the scene changes.
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const built = buildScene('slab', { pattern: 'noise', aspect: 64 / 36 });
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0]);
      const hud = new THREE.Scene();
      const badge = new THREE.Mesh(new THREE.PlaneGeometry(0.3, 0.3), new THREE.MeshBasicMaterial({ color: 0xffff00 }));
      badge.position.set(-2, 1, 1);
      hud.add(badge);
      const overlay = new RenderPass(hud, built.camera);
      overlay.clear = false;
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.addPass(overlay);
      composer.render();
      sss.enabled = false;
      const hookLeft = Object.hasOwn(built.scene, 'onAfterRender'); // watching while disabled
      const before = await read(renderer, composer.readBuffer);
      built.subsurface[0].color.setRGB(0.2, 0.2, 1);
      for (let i = 0; i < 8; i++) composer.render();
      const frozen = await read(renderer, composer.readBuffer);
      // Enabled again it draws; the warning is not repeated when disabled again.
      sss.enabled = true;
      composer.render();
      const live = await read(renderer, composer.readBuffer);
      sss.enabled = false;
      for (let i = 0; i < 8; i++) composer.render();
      sss.dispose();
      const hookAfterDispose = Object.hasOwn(built.scene, 'onAfterRender');
      composer.dispose();
      return { before, frozen, live, hookLeft, hookAfterDispose };
    });
    expect(frozenWarnings()).toHaveLength(1);
    expect(frozenWarnings()[0]).toMatch(/set scattering = false \(in version 0\.1 that was enabled = false\)/);
    expect(compare(r.frozen, r.before, 0).worst).toBe(0); // frozen indeed
    expect(compare(r.live, r.before, 1e-3).differing).toBeGreaterThan(0.5); // the colour change shows once enabled
    expect(r.hookLeft).toBe(true);
    expect(r.hookAfterDispose).toBe(false); // the scene as it was after dispose
  });
});

describe('renderer.setEffects (three r182+)', () => {
  it("setEffects([sss]) draws the composer path's pixels, and the renderer skips its own draw of the scene (isRenderPass)", async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, EffectComposer, OutputPass, buildScene, DEFAULTS } = window.lab;
      const { width, height } = DEFAULTS;
      const renderer = new THREE.WebGLRenderer({ antialias: false, outputBufferType: THREE.HalfFloatType });
      renderer.setPixelRatio(1);
      renderer.setSize(width, height, false);
      // No tone mapping: on a renderer with an output buffer, OutputPass's tone mapping in the
      // composer path would be applied again by the renderer's output (setEffects needs no OutputPass).
      const built = buildScene('mixed', { intensity: 2 });
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0], { widthMm: 1 });
      // Draws of an ordinary mesh per frame: the pipeline's own is one (its first call).
      const ordinary = built.scene.children.find((o) => o.isMesh && !built.subsurface.includes(o.material));
      let draws = 0;
      ordinary.onBeforeRender = () => { draws++; };
      const gl = renderer.getContext();
      const canvas = () => {
        const pixels = new Uint8Array(width * height * 4);
        gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        return Array.from(pixels);
      };
      const frame = (draw) => { draws = 0; draw(); return { pixels: canvas(), draws }; };

      const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.HalfFloatType }));
      composer.addPass(sss);
      composer.addPass(new OutputPass());
      composer.render(); // compile
      const viaComposer = frame(() => composer.render());
      renderer.setEffects([sss]);
      renderer.render(built.scene, built.camera); // compile
      const viaEffects = frame(() => renderer.render(built.scene, built.camera));
      sss.isRenderPass = false;
      renderer.setEffects([sss]);
      const withSceneDraw = frame(() => renderer.render(built.scene, built.camera));
      renderer.setEffects(null);
      sss.dispose();
      composer.dispose();
      const glError = gl.getError();
      renderer.dispose();
      return { viaComposer, viaEffects, withSceneDraw, glError, revision: THREE.REVISION };
    });
    expect(Number(r.revision)).toBeGreaterThanOrEqual(182);
    expect(r.glError).toBe(0);
    let worst = 0;
    let lit = 0;
    for (let i = 0; i < r.viaComposer.pixels.length; i++) {
      worst = Math.max(worst, Math.abs(r.viaComposer.pixels[i] - r.viaEffects.pixels[i]));
      if (i % 4 === 0 && r.viaComposer.pixels[i] > 10) lit++;
    }
    expect(lit).toBeGreaterThan(1000); // a picture, not a black frame
    expect(worst).toBeLessThanOrEqual(1); // 8-bit canvas: at most one level apart
    expect(r.withSceneDraw.pixels).toEqual(r.viaEffects.pixels);
    expect(r.viaComposer.draws).toBe(1);
    expect(r.viaEffects.draws).toBe(1); // the renderer's own draw skipped
    expect(r.withSceneDraw.draws).toBe(2); // without isRenderPass it draws the scene first, for nothing
  });
});
