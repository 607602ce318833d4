// three's own shadows beside the light depth pass: with the pipeline's light casting shadows and
// the light depth pass running (the light behind a subsurface sphere), every pixel outside the
// subsurface mesh (a floor and an ordinary box, both receiving) is plain three's (a RenderPass frame), for dynamic shadow maps and for static ones
// (shadowMap.autoUpdate false, needsUpdate true: drawn once, then kept), for each shadow type.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, closeCheckedPage } from '../../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(() => closeCheckedPage(page));

/**
 * In the page: a sphere (subsurface in the pipeline's frames) on a floor, lit from behind and above
 * by a shadow-casting DirectionalLight that is also the pipeline's light; `frames` frames drawn
 * through the pipeline (scattering off: only transmittance changes subsurface pixels) and through a
 * RenderPass, each on its own renderer with the same shadow settings. Returns the largest
 * difference over the pixels the pipeline's mask leaves out, how many of them the sphere's shadow
 * darkens by over 10 % (against the same frame without shadows), and whether the light depth pass ran.
 */
function compare({ shadowType, staticShadows, frames }) {
  return page.evaluate(async (o) => {
    const { THREE, SSS, RenderPass, createRenderer, createComposer, read } = window.lab;
    const width = 96, height = 64;
    const frame = async (withPipeline, { debugView = 'final', castShadow = true } = {}) => {
      const renderer = createRenderer(width, height);
      Object.assign(renderer.shadowMap, { enabled: true, type: THREE[o.shadowType], autoUpdate: !o.staticShadows, needsUpdate: true });
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera(35, width / height, 0.1, 50);
      camera.position.set(0, 1.2, 6);
      camera.lookAt(0, 0, 0);
      const sphere = new THREE.Mesh(new THREE.SphereGeometry(0.6, 48, 24), new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.7 }));
      const floor = new THREE.Mesh(new THREE.PlaneGeometry(8, 8), new THREE.MeshStandardMaterial({ color: 0x999999, roughness: 0.9 }));
      floor.rotation.x = -Math.PI / 2;
      floor.position.y = -0.6;
      // An ordinary box casting and receiving: a closed mesh's lit faces show acne where its shadow
      // map holds the faces that face the light (three draws the back faces of a front-sided material).
      const box = new THREE.Mesh(new THREE.BoxGeometry(0.8, 0.8, 0.8), new THREE.MeshStandardMaterial({ color: 0x6688cc, roughness: 0.6 }));
      box.position.set(-1.4, -0.2, 0.4);
      box.rotation.y = 0.5;
      box.castShadow = box.receiveShadow = true;
      sphere.castShadow = true;
      floor.receiveShadow = true;
      const light = new THREE.DirectionalLight(0xffffff, 3);
      light.position.set(1, 4, -3); // behind the sphere and above: its shadow falls on the floor towards the camera
      light.castShadow = castShadow;
      Object.assign(light.shadow.camera, { left: -3, right: 3, top: 3, bottom: -3, near: 0.5, far: 12 });
      light.shadow.mapSize.set(256, 256);
      scene.add(sphere, box, floor, light, light.target, new THREE.AmbientLight(0xffffff, 0.3));
      const composer = createComposer(renderer);
      let sss = null;
      if (withPipeline) {
        sss = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000, scattering: false, debugView, lightDepthSize: 128 });
        sss.makeSubsurface(sphere.material);
        composer.addPass(sss);
      } else {
        composer.addPass(new RenderPass(scene, camera));
      }
      for (let i = 0; i < o.frames; i++) composer.render();
      const pixels = await read(renderer, composer.readBuffer);
      const lightDepthRan = sss?._lightDepth.valid ?? false;
      sss?.dispose();
      composer.dispose();
      renderer.dispose();
      renderer.forceContextLoss();
      return { pixels, lightDepthRan };
    };
    const plain = await frame(false);
    const unshadowed = (await frame(false, { castShadow: false })).pixels;
    const piped = await frame(true);
    const mask = (await frame(true, { debugView: 'mask' })).pixels;
    let worst = 0, compared = 0, shadowed = 0;
    for (let i = 0; i < width * height; i++) {
      if (mask[4 * i] > 0) continue; // the subsurface sphere (its transmittance is the pipeline's)
      compared++;
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(piped.pixels[4 * i + c] - plain.pixels[4 * i + c]));
      if (plain.pixels[4 * i] < 0.9 * unshadowed[4 * i]) shadowed++; // the sphere's shadow on the floor
    }
    return { worst, compared, shadowed, lightDepthRan: piped.lightDepthRan };
  }, { shadowType, staticShadows, frames });
}

describe("three's shadows beside the light depth pass", () => {
  for (const shadowType of ['BasicShadowMap', 'PCFShadowMap', 'VSMShadowMap']) {
    for (const staticShadows of [false, true]) {
      it(`${shadowType}, ${staticShadows ? 'static (needsUpdate once)' : 'dynamic'}: the pixels outside the subsurface mesh are plain three's`, async () => {
        const r = await compare({ shadowType, staticShadows, frames: 2 });
        expect(r.lightDepthRan).toBe(true); // the light depth pass ran, so it could have disturbed them
        expect(r.compared).toBeGreaterThan(4000);
        expect(r.shadowed).toBeGreaterThan(50); // the shadow is in the compared pixels
        expect(r.worst, JSON.stringify(r)).toBeLessThan(2e-3);
      });
    }
  }
});
