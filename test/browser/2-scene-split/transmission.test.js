// Materials with `transmission` (glTF's KHR_materials_transmission) beside subsurface ones (issue
// 36): glass in front of a subsurface sphere shows it as three draws it, unscattered (three's
// transmission pass draws the opaque scene again into a picture of its own, where no pipeline
// splits it), which the README says; a transparent pane shows it scattered. A transmissive
// material made subsurface is refused (test/reliability/badInputs.js).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { evaluateFloats, openPage, closeCheckedPage } from '../../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(() => closeCheckedPage(page));

/** A textured subsurface sphere behind a pane of `kind` glass: the pipeline's frame and a RenderPass's, float. */
function paneFrames(kind) {
  return evaluateFloats(page, async (glassKind) => {
    const { THREE, SSS, RenderPass, createRenderer, createComposer, read, dataTexture } = window.lab;
    const renderer = createRenderer(64, 64);
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 10);
    camera.position.set(0, 0, 0.3);
    const map = dataTexture(16, 16, (x, y) => ((x + y) % 2 ? [1, 0.8, 0.7] : [0.2, 0.1, 0.1]));
    const skin = new THREE.MeshStandardMaterial({ map, roughness: 1 });
    const light = new THREE.DirectionalLight(0xffffff, 3);
    light.position.set(0, 0, 1);
    const glass = glassKind === 'transparent'
      ? new THREE.MeshStandardMaterial({ transparent: true, opacity: 0.3, roughness: 0 })
      : new THREE.MeshPhysicalMaterial({ transmission: 1, roughness: 0, thickness: 0 });
    const pane = new THREE.Mesh(new THREE.PlaneGeometry(0.2, 0.05), glass); // rows 26 to 38 of 64
    pane.position.z = 0.08;
    scene.add(new THREE.Mesh(new THREE.SphereGeometry(0.05, 48, 32), skin), light, light.target, pane);
    const frame = async (pass) => {
      const composer = createComposer(renderer, { type: THREE.FloatType });
      composer.addPass(pass);
      composer.render();
      const out = await read(renderer, composer.readBuffer);
      composer.dispose();
      return out;
    };
    const plain = await frame(new RenderPass(scene, camera));
    const sss = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: 1000, type: THREE.FloatType });
    sss.makeSubsurface(skin);
    const scattered = await frame(sss);
    sss.dispose();
    renderer.dispose();
    return { plain, scattered };
  }, kind);
}

/** The largest RGB difference over columns 20..43 of rows y0..y1. */
function worst(a, b, y0, y1) {
  let m = 0;
  for (let y = y0; y < y1; y++) for (let x = 20; x < 44; x++) for (let c = 0; c < 3; c++) m = Math.max(m, Math.abs(a[(y * 64 + x) * 4 + c] - b[(y * 64 + x) * 4 + c]));
  return m;
}

describe('glass in front of a subsurface sphere', () => {
  it('with transmission: behind it the sphere as three draws it, unscattered (exactly); around it scattered', async () => {
    const r = await paneFrames('transmission');
    expect(worst(r.scattered, r.plain, 29, 35)).toBe(0);
    expect(worst(r.scattered, r.plain, 10, 20)).toBeGreaterThan(0.02);
  });

  it('transparent: behind it the sphere scattered, as around it', async () => {
    const r = await paneFrames('transparent');
    expect(worst(r.scattered, r.plain, 29, 35)).toBeGreaterThan(0.02);
  });
});
