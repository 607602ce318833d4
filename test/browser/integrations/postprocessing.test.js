// three-separable-sss/postprocessing: the pipeline as a Pass of pmndrs `postprocessing`'s
// EffectComposer (the real package), in place of its RenderPass. The oracle is the three.js
// composer path: the same head, the same settings, through three's EffectComposer.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../../harness/page.js';

let page;
beforeAll(async () => {
  page = await openPage('/test/pages/postprocessing.html');
});
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

/** Largest |a − b| over RGB, and the mean |a − b|, over the pixels `where` (RGBA index of the pixel) keeps. */
function difference(a, b, where = () => true) {
  let worst = 0;
  let sum = 0;
  let count = 0;
  for (let i = 0; i < a.length; i++) {
    if (i % 4 === 3 || !where(i - (i % 4))) continue;
    const d = Math.abs(a[i] - b[i]);
    worst = Math.max(worst, d);
    sum += d;
    count++;
  }
  return { worst, mean: sum / count };
}

const WIDTH = 320;
const HEIGHT = 180;

describe('SubsurfaceScatteringPass in pmndrs EffectComposer', () => {
  it('renders the head as the three.js composer path does (within 1e-3), and scatters', async () => {
    const r = await evaluateFloats(page, async (width, height) => {
      const { THREE, SSS, createRenderer, createComposer, read } = window.lab;
      const { POSTPROCESSING: PP, SubsurfaceScatteringPass, headRig, HEAD_WORLD_UNIT_IN_MM } = window.pp;
      const renderer = createRenderer(width, height);
      const options = (rig) => ({ scene: rig.scene, camera: rig.camera, light: rig.light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM });

      // The oracle: three's EffectComposer with the three.js pass.
      const rigA = await headRig(width / height);
      const sss = new SSS.SubsurfaceScattering(options(rigA));
      sss.makeSubsurface(rigA.head.material);
      const three = createComposer(renderer);
      three.addPass(sss);
      three.render();
      const oracle = await read(renderer, three.readBuffer);
      sss.scattering = false;
      three.render();
      const unscattered = await read(renderer, three.readBuffer);

      // pmndrs's EffectComposer, half-float buffers, the pass in place of its RenderPass.
      const rigB = await headRig(width / height);
      const composer = new PP.EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
      composer.autoRenderToScreen = false; // read the buffers back instead
      const pass = new SubsurfaceScatteringPass(options(rigB));
      pass.makeSubsurface(rigB.head.material);
      composer.addPass(pass);
      composer.render(0);
      const out = await read(renderer, composer.inputBuffer); // needsSwap false: the input buffer
      const result = {
        oracle, unscattered, out, isStandIn: rigA.isStandIn, needsSwap: pass.needsSwap,
        kernelPixels: pass.pipeline.plan.kernelPixels, glError: renderer.getContext().getError(),
      };
      sss.dispose();
      three.dispose();
      composer.dispose();
      renderer.dispose();
      renderer.forceContextLoss();
      return result;
    }, WIDTH, HEIGHT);
    expect(r.glError).toBe(0);
    expect(r.isStandIn).toBe(false); // the scan itself (npm test's asset step provides it)
    expect(r.needsSwap).toBe(false);
    expect(r.kernelPixels).toBeGreaterThan(1);
    // It scatters: the scattered image differs from the unscattered one on the skin...
    expect(difference(r.oracle, r.unscattered).worst).toBeGreaterThan(0.02);
    // ...and the pmndrs path draws the same image as the three.js path.
    const d = difference(r.out, r.oracle);
    expect(d.worst).toBeLessThan(1e-3);
    expect(d.mean).toBeLessThan(1e-5);
  });

  it('composes with EffectPass effects: bloom and tone mapping see what the three.js path draws', async () => {
    const r = await evaluateFloats(page, async (width, height) => {
      const { THREE, SSS, createRenderer, createComposer, read } = window.lab;
      const { POSTPROCESSING: PP, SubsurfaceScatteringPass, headRig, copyTexture, HEAD_WORLD_UNIT_IN_MM } = window.pp;
      const renderer = createRenderer(width, height);
      const options = (rig) => ({ scene: rig.scene, camera: rig.camera, light: rig.light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM });
      const effects = (camera) => new PP.EffectPass(camera,
        new PP.BloomEffect({ intensity: 2, luminanceThreshold: 0.2, mipmapBlur: true }),
        new PP.ToneMappingEffect({ mode: PP.ToneMappingMode.ACES_FILMIC }));

      // The oracle: the three.js path's image copied into a pmndrs composer's input buffer, then
      // the same effects.
      const rigA = await headRig(width / height);
      const sss = new SSS.SubsurfaceScattering(options(rigA));
      sss.makeSubsurface(rigA.head.material);
      const three = createComposer(renderer);
      three.addPass(sss);
      three.render();
      const oracleComposer = new PP.EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
      oracleComposer.autoRenderToScreen = false;
      oracleComposer.addPass(effects(rigA.camera));
      copyTexture(renderer, three.readBuffer.texture, oracleComposer.inputBuffer);
      oracleComposer.render(0);
      const oracle = await read(renderer, oracleComposer.outputBuffer); // one swap: the output buffer

      const rigB = await headRig(width / height);
      const composer = new PP.EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
      composer.autoRenderToScreen = false;
      const pass = new SubsurfaceScatteringPass(options(rigB));
      pass.makeSubsurface(rigB.head.material);
      composer.addPass(pass);
      composer.addPass(effects(rigB.camera));
      composer.render(0);
      const out = await read(renderer, composer.outputBuffer);
      const before = await read(renderer, composer.inputBuffer);
      const result = { oracle, out, before, glError: renderer.getContext().getError() };
      sss.dispose();
      three.dispose();
      oracleComposer.dispose();
      composer.dispose();
      renderer.dispose();
      renderer.forceContextLoss();
      return result;
    }, WIDTH, HEIGHT);
    expect(r.glError).toBe(0);
    // The effects did something (tone mapping and bloom change every lit pixel)...
    expect(difference(r.out, r.before).worst).toBeGreaterThan(0.05);
    // ...to the same image as the three.js path.
    const d = difference(r.out, r.oracle);
    expect(d.worst).toBeLessThan(2e-3);
    expect(d.mean).toBeLessThan(1e-4);
  });

  it("leaves the scene's depth for effects that read it, as pmndrs's RenderPass does", async () => {
    const r = await evaluateFloats(page, async (width, height) => {
      const { THREE, createRenderer, read } = window.lab;
      const { POSTPROCESSING: PP, SubsurfaceScatteringPass, headRig, HEAD_WORLD_UNIT_IN_MM } = window.pp;
      const renderer = createRenderer(width, height);
      const depthOf = async (firstPass, rig) => {
        const composer = new PP.EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
        composer.autoRenderToScreen = false;
        composer.addPass(firstPass);
        composer.addPass(new PP.EffectPass(rig.camera, new PP.DepthEffect()));
        composer.render(0);
        const depth = await read(renderer, composer.outputBuffer);
        composer.dispose();
        return depth;
      };
      const rigA = await headRig(width / height);
      const oracle = await depthOf(new PP.RenderPass(rigA.scene, rigA.camera), rigA);
      const rigB = await headRig(width / height);
      const pass = new SubsurfaceScatteringPass({ scene: rigB.scene, camera: rigB.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM });
      pass.makeSubsurface(rigB.head.material);
      const out = await depthOf(pass, rigB);
      let onHead = 0;
      for (let i = 0; i < oracle.length; i += 4) if (oracle[i] < 0.999) onHead++;
      const result = { oracle, out, onHead, glError: renderer.getContext().getError() };
      renderer.dispose();
      renderer.forceContextLoss();
      return result;
    }, WIDTH, HEIGHT);
    expect(r.glError).toBe(0);
    expect(r.onHead).toBeGreaterThan(0.1 * WIDTH * HEIGHT); // the head covers the view
    expect(difference(r.out, r.oracle).worst).toBeLessThan(1e-3);
  });

  it('refuses 8-bit composer buffers with a RangeError naming the fix, and follows setMainCamera', async () => {
    const r = await page.evaluate(async (width, height) => {
      const { THREE, createRenderer } = window.lab;
      const { POSTPROCESSING: PP, SubsurfaceScatteringPass, headRig, HEAD_WORLD_UNIT_IN_MM } = window.pp;
      const renderer = createRenderer(width, height);
      const rig = await headRig(width / height);
      const pass = new SubsurfaceScatteringPass({ scene: rig.scene, camera: rig.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM });
      let error = null;
      try {
        new PP.EffectComposer(renderer).addPass(pass); // pmndrs's default: UnsignedByteType
      } catch (e) {
        error = `${e.name}: ${e.message}`;
      }
      const composer = new PP.EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
      composer.addPass(pass);
      const other = rig.camera.clone();
      composer.setMainCamera(other);
      const followed = pass.pipeline.camera === other && pass.camera === other;
      let badOption = null;
      try {
        new SubsurfaceScatteringPass({ scene: rig.scene, camera: rig.camera, method: 'fast' });
      } catch (e) {
        badOption = `${e.name}: ${e.message}`;
      }
      pass.dispose();
      composer.dispose();
      renderer.dispose();
      renderer.forceContextLoss();
      return { error, followed, badOption };
    }, WIDTH, HEIGHT);
    expect(r.error).toMatch(/^RangeError: .*UnsignedByteType.*frameBufferType: THREE\.HalfFloatType/);
    expect(r.followed).toBe(true);
    expect(r.badOption).toMatch(/^RangeError: .*method/);
  });

  it('as the last pass draws to the screen with the renderer\'s tone mapping and sRGB, as three\'s RenderPass and OutputPass do (pmndrs and three.js composers)', async () => {
    const r = await page.evaluate(async (width, height) => {
      const { THREE, SSS, EffectComposer, RenderPass, OutputPass, createRenderer } = window.lab;
      const { POSTPROCESSING: PP, SubsurfaceScatteringPass } = window.pp;
      const renderer = createRenderer(width, height);
      renderer.toneMapping = THREE.ACESFilmicToneMapping;
      // A lit cube on a coloured background, no subsurface material: the pass adds nothing there.
      const scene = new THREE.Scene();
      scene.background = new THREE.Color(0x203040);
      const cube = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshStandardMaterial({ color: 0xc08060, roughness: 0.6 }));
      cube.rotation.set(0.5, 0.7, 0);
      scene.add(cube, new THREE.AmbientLight(0xffffff, 0.3));
      const sun = new THREE.DirectionalLight(0xffffff, 3);
      sun.position.set(2, 3, 4);
      scene.add(sun);
      // A half-transparent pane in front of the cube, inside its outline (drawn after the compose).
      const pane = new THREE.Mesh(new THREE.PlaneGeometry(0.3, 0.3), new THREE.MeshStandardMaterial({ color: 0x40a0ff, transparent: true, opacity: 0.5 }));
      pane.position.set(0, 0, 1);
      scene.add(pane);
      const camera = new THREE.PerspectiveCamera(40, width / height, 0.1, 20);
      camera.position.set(0, 0, 3);
      const gl = renderer.getContext();
      // The canvas, read in the task that drew it (the drawing buffer is not preserved).
      const screen = (render) => {
        render();
        renderer.setRenderTarget(null);
        const pixels = new Uint8Array(width * height * 4);
        gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        return Array.from(pixels);
      };
      const images = {};
      const pmndrs = (pass) => {
        const composer = new PP.EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
        composer.addPass(pass);
        const image = screen(() => composer.render(0));
        composer.dispose();
        return image;
      };
      images.pmndrsRender = pmndrs(new PP.RenderPass(scene, camera));
      images.pmndrsOurs = pmndrs(new SubsurfaceScatteringPass({ scene, camera }));
      // Without the pane: what OutputPass tone-maps after blending (in linear light) is the same.
      pane.visible = false;
      images.pmndrsRenderOpaque = pmndrs(new PP.RenderPass(scene, camera));
      images.pmndrsOursOpaque = pmndrs(new SubsurfaceScatteringPass({ scene, camera }));
      const three = (...passes) => {
        const size = renderer.getDrawingBufferSize(new THREE.Vector2());
        const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(size.x, size.y, { type: THREE.HalfFloatType }));
        for (const pass of passes) composer.addPass(pass); // the last one: the composer draws it to the screen
        const image = screen(() => composer.render());
        composer.dispose();
        for (const pass of passes) pass.dispose();
        return image;
      };
      images.threeOutput = three(new RenderPass(scene, camera), new OutputPass()); // three's linear-HDR pipeline's end
      images.threeOurs = three(new SSS.SubsurfaceScattering({ scene, camera }));
      const result = { images, glError: gl.getError() };
      renderer.dispose();
      renderer.forceContextLoss();
      return result;
    }, WIDTH, HEIGHT);
    expect(r.glError).toBe(0);
    // An opaque scene: on both composers the pass's screen is three's RenderPass + OutputPass
    // screen (the background tone-mapped too, as OutputPass does it)...
    expect(difference(r.images.threeOurs, r.images.threeOutput).worst).toBeLessThanOrEqual(1);
    expect(difference(r.images.pmndrsOursOpaque, r.images.threeOutput).worst).toBeLessThanOrEqual(1);
    // ...and with the pane, the cube and the pane over it are what pmndrs's RenderPass draws in
    // that place: three tone-maps and encodes each material drawn to the screen, the pane blended
    // over the encoded cube (a cleared background colour it only encodes: 0x203040).
    const background = r.images.pmndrsRender.slice(0, 3);
    expect(background).toEqual([32, 48, 64]);
    const onCube = (i) => [0, 1, 2].some((c) => Math.abs(r.images.pmndrsRender[i + c] - background[c]) > 2);
    const cubePixels = r.images.pmndrsRender.filter((_, i) => i % 4 === 0 && onCube(i)).length;
    expect(cubePixels).toBeGreaterThan(0.05 * WIDTH * HEIGHT);
    const underPane = r.images.pmndrsRender.filter((v, i) => i % 4 === 0 && Math.abs(v - r.images.pmndrsRenderOpaque[i]) > 8).length;
    expect(underPane).toBeGreaterThan(0.005 * WIDTH * HEIGHT);
    expect(difference(r.images.pmndrsOurs, r.images.pmndrsRender, onCube).worst).toBeLessThanOrEqual(1);
  });
});
