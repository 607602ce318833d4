// three.js pass conventions: setSize, dispose back to the memory baseline, renderer state
// restored, OutputPass last, float/half-float targets only, and clear errors on bad set-ups.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage } from '../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

describe('pass conventions', () => {
  it('setSize resizes every target; dispose frees every target, texture and quad', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, createComposer, RenderPass } = window.lab;
      const renderer = createRenderer(64, 36);
      const scene = new THREE.Scene();
      const material = new THREE.MeshStandardMaterial();
      scene.add(new THREE.Mesh(new THREE.PlaneGeometry(4, 4), material));
      const light = new THREE.SpotLight(0xffffff, 3);
      light.position.set(0, 0, -5);
      scene.add(light, light.target);
      const camera = new THREE.PerspectiveCamera(30, 16 / 9, 0.1, 50);
      camera.position.z = 5;
      const composer = createComposer(renderer);
      composer.addPass(new RenderPass(scene, camera));
      composer.render();
      const baseline = { ...renderer.info.memory };

      const sss = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 100 });
      const hook = sss.makeSubsurface(material, { widthMm: 2 });
      const pipeline = createComposer(renderer);
      pipeline.addPass(sss);
      pipeline.render();
      pipeline.setSize(80, 45);
      pipeline.render();
      const sizes = {
        scene: [sss._scenePass.renderTarget.width, sss._scenePass.renderTarget.height],
        horizontal: sss._blur.horizontalPass.uniforms.resolution.value.toArray(),
        vertical: sss._blur.verticalPass.uniforms.resolution.value.toArray(),
      };
      const types = sss._scenePass.renderTarget.textures.map((t) => t.type);
      const during = { ...renderer.info.memory };
      sss.dispose();
      const unhooked = !material.customProgramCacheKey().includes('subsurface') && SSS.getSubsurface(material) === undefined;
      pipeline.dispose();
      hook.dispose();
      composer.render();
      const after = { ...renderer.info.memory };
      return { baseline, during, after, sizes, types, unhooked, halfFloat: THREE.HalfFloatType, float: THREE.FloatType };
    });
    expect(r.sizes).toEqual({ scene: [80, 45], horizontal: [80, 45], vertical: [80, 45] });
    for (const t of r.types) expect([r.halfFloat, r.float]).toContain(t);
    expect(r.during.textures).toBeGreaterThan(r.baseline.textures);
    expect(r.after).toEqual(r.baseline);
    expect(r.unhooked).toBe(true); // dispose also gives the material back its own shader
  });

  it('scattering = false releases the blur\'s targets (2 textures); back on, they come back and the frame is as before', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, createComposer, read, dataTexture } = window.lab;
      const renderer = createRenderer(64, 36);
      const scene = new THREE.Scene();
      const checker = dataTexture(8, 8, (x, y) => ((x + y) % 2 ? [1, 1, 1] : [0.05, 0.05, 0.05])); // what the blur softens
      const material = new THREE.MeshStandardMaterial({ color: 0xffccaa, map: checker });
      const disc = new THREE.Mesh(new THREE.CircleGeometry(1, 32), material);
      scene.add(disc, new THREE.AmbientLight(0xffffff, 1));
      const camera = new THREE.PerspectiveCamera(30, 16 / 9, 0.1, 50);
      camera.position.z = 5;
      const sss = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: 10 });
      sss.makeSubsurface(material, { widthMm: 8 });
      const composer = createComposer(renderer, { type: THREE.FloatType });
      composer.addPass(sss);
      const frame = async () => { composer.render(); return { textures: renderer.info.memory.textures, pixels: await read(renderer, composer.readBuffer) }; };
      const on = await frame();
      sss.scattering = false;
      const off = await frame();
      sss.scattering = true;
      const again = await frame();
      const blurred = sss.plan.blur;
      sss.dispose();
      composer.dispose();
      renderer.dispose();
      checker.dispose();
      let most = 0;
      for (let i = 0; i < on.pixels.length; i++) most = Math.max(most, Math.abs(on.pixels[i] - again.pixels[i]));
      let changed = 0;
      for (let i = 0; i < on.pixels.length; i++) changed = Math.max(changed, Math.abs(on.pixels[i] - off.pixels[i]));
      return { textures: [on.textures, off.textures, again.textures], most, changed, blurred };
    });
    expect(r.blurred).toBe(true);
    expect(r.changed).toBeGreaterThan(1e-3); // the blur showed
    expect(r.textures[1]).toBe(r.textures[0] - 2); // the horizontal pass's and the scattered light's
    expect(r.textures[2]).toBe(r.textures[0]);
    expect(r.most).toBe(0);
  });

  it('restores the renderer state it touches and works before OutputPass', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, OutputPass, EffectComposer } = window.lab;
      const renderer = createRenderer(64, 36);
      const scene = new THREE.Scene();
      const material = new THREE.MeshStandardMaterial({ color: 0xffffff });
      scene.add(new THREE.Mesh(new THREE.PlaneGeometry(4, 4), material), new THREE.AmbientLight(0xffffff, 1));
      const light = new THREE.DirectionalLight(0xffffff, 2);
      light.position.set(0, 0, 5);
      scene.add(light, light.target);
      const camera = new THREE.PerspectiveCamera(30, 16 / 9, 0.1, 50);
      camera.position.z = 5;
      const sss = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 100 });
      sss.makeSubsurface(material, { widthMm: 2 });

      const other = new THREE.WebGLRenderTarget(8, 8);
      renderer.setRenderTarget(other);
      renderer.setClearColor(new THREE.Color(0.1, 0.2, 0.3), 0.4);
      renderer.autoClear = false;
      sss._lightDepth.render(renderer, scene);
      sss._scenePass.render(renderer, null, null);
      const state = {
        target: renderer.getRenderTarget() === other,
        clear: renderer.getClearColor(new THREE.Color()).toArray(),
        alpha: renderer.getClearAlpha(),
        autoClear: renderer.autoClear,
        background: scene.background,
        visible: material.visible,
        override: scene.overrideMaterial,
      };
      renderer.setRenderTarget(null);
      renderer.autoClear = true;

      const composer = new EffectComposer(renderer);
      composer.addPass(sss);
      composer.addPass(new OutputPass());
      composer.render();
      const gl = renderer.getContext();
      const pixels = new Uint8Array(4);
      gl.readPixels(32, 18, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      const error = gl.getError();
      sss.dispose();
      composer.dispose();
      return { state, centre: Array.from(pixels), error };
    });
    expect(r.state.target).toBe(true);
    expect(r.state.clear.map((v) => +v.toFixed(4))).toEqual([0.1, 0.2, 0.3]);
    expect(r.state.alpha).toBeCloseTo(0.4, 6);
    expect(r.state.autoClear).toBe(false);
    expect(r.state.background).toBe(null);
    expect(r.state.visible).toBe(true);
    expect(r.state.override).toBe(null);
    expect(r.error).toBe(0);
    // Through OutputPass to the canvas: a lit, tone-mapped, non-black surface.
    expect(Math.min(...r.centre.slice(0, 3))).toBeGreaterThan(60);
  });
});

describe('bad set-ups get clear errors, never a black frame', () => {
  it('a renderer without float render targets, or a WebGL1 one, is refused with a message naming what is missing', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, createComposer } = window.lab;
      const renderer = createRenderer(16, 16);
      const has = renderer.extensions.has.bind(renderer.extensions);
      renderer.extensions.has = (name) => name !== 'EXT_color_buffer_float' && has(name);
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera();
      const sss = new SSS.SubsurfaceScattering({ scene, camera });
      const composer = createComposer(renderer);
      composer.addPass(sss);
      const messages = [];
      try { composer.render(); } catch (e) { messages.push(e.message); }
      const webgl1 = { isWebGLRenderer: true, getContext: () => null, capabilities: { isWebGL2: false }, extensions: { has: () => true } };
      try { sss._scenePass.render(webgl1); } catch (e) { messages.push(e.message); }
      try { new SSS.LightDepthTarget(new THREE.DirectionalLight()).render(webgl1, scene); } catch (e) { messages.push(e.message); }
      return messages;
    });
    expect(r).toHaveLength(3);
    expect(r[0]).toMatch(/EXT_color_buffer_float/);
    expect(r[1]).toMatch(/WebGL2/);
    expect(r[2]).toMatch(/WebGL2/);
  });
});
