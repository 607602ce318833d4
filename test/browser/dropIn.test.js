// The pipeline as a drop-in Pass in an ordinary three.js frame (issue 9), against plain three.js
// as the oracle: transparent objects, passes before and after it, depth, MSAA, camera switches,
// two pipelines on one material, lights outside the scene, insertPass/removePass, clear colour.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openLabPage, closeCheckedPage, evaluateFloats } from '../harness/page.js';

let page;
const warnings = [];
beforeAll(async () => { page = await openLabPage(warnings); });
afterAll(() => closeCheckedPage(page));

/** Largest |a − b| over RGB of the pixels `where(i)` picks (all by default), and how many it looked at. */
function maxDifference(a, b, where = () => true) {
  let worst = 0;
  let count = 0;
  for (let i = 0; i < a.length / 4; i++) {
    if (!where(i)) continue;
    count++;
    for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(a[i * 4 + c] - b[i * 4 + c]));
  }
  return { worst, count };
}

describe('transparent objects', () => {
  it("glass in front of skin equals plain three's glass over the pipeline's own opaque result; glass behind skin stays hidden", async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { pattern: 'noise', slabSize: 3 });
      const glassMaterial = () => new THREE.MeshStandardMaterial({ color: 0x88bbff, transparent: true, opacity: 0.6, roughness: 0.3 });
      const front = new THREE.Mesh(new THREE.PlaneGeometry(2, 4), glassMaterial());
      front.position.set(-1.5, 0, 1); // over the left half of the slab, nearer the camera
      const behind = new THREE.Mesh(new THREE.PlaneGeometry(2, 4), glassMaterial());
      behind.position.set(1.5, 0, -1); // behind the right half: hidden where the slab is
      built.scene.add(front, behind);
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0], { widthMm: 1 });
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.render();
      const withGlass = await read(renderer, composer.readBuffer);

      // The pipeline's own opaque result, then three's RenderPass blending the same glass over it
      // (depth-tested against the depth the pipeline leaves, which the next test checks).
      front.visible = behind.visible = false;
      const glassScene = new THREE.Scene();
      const copies = [front.clone(), behind.clone()];
      for (const copy of copies) copy.visible = true;
      const lightCopy = built.light.clone();
      glassScene.add(...copies, lightCopy, lightCopy.target);
      const overlay = new RenderPass(glassScene, built.camera);
      overlay.clear = false;
      composer.addPass(overlay);
      composer.render();
      const oracle = await read(renderer, composer.readBuffer);
      overlay.enabled = false;
      composer.render();
      const opaque = await read(renderer, composer.readBuffer);
      const surface = await read(renderer, sss._scenePass.renderTarget, 2);
      // Screen columns of the two glass planes, from the camera.
      const toPixel = (x) => ((new THREE.Vector3(x, 0, 0).project(built.camera).x + 1) / 2) * DEFAULTS.width;
      const columns = { front: [toPixel(-2.5), toPixel(-0.5)], behind: [toPixel(0.5), toPixel(2.5)] };
      sss.dispose();
      composer.dispose();
      return { withGlass, oracle, opaque, surface, columns, width: DEFAULTS.width, glError: renderer.getContext().getError() };
    });
    expect(r.glError).toBe(0);
    const column = (i) => i % r.width;
    const inFront = (i) => column(i) > r.columns.front[0] + 1 && column(i) < r.columns.front[1] - 1;
    const behindOnSlab = (i) => column(i) > r.columns.behind[0] + 1 && column(i) < r.columns.behind[1] - 1 && r.surface[i * 4 + 1] > 0;
    const front = maxDifference(r.withGlass, r.oracle, inFront);
    expect(front.count).toBeGreaterThan(1000);
    expect(front.worst).toBeLessThan(1e-3);
    // The glass does attenuate: the result differs from the unglazed skin there.
    expect(maxDifference(r.withGlass, r.opaque, inFront).worst).toBeGreaterThan(0.05);
    const hidden = maxDifference(r.withGlass, r.opaque, behindOnSlab);
    expect(hidden.count).toBeGreaterThan(500);
    expect(hidden.worst).toBeLessThan(1e-6);
    expect(maxDifference(r.withGlass, r.oracle).worst).toBeLessThan(1e-3); // everywhere else too
  });

  it('a transparent subsurface material is drawn (blended, unscattered) with one warning naming it', async () => {
    warnings.length = 0;
    const r = await evaluateFloats(page, async () => {
      const { SSS, createRenderer, createComposer, read, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const built = buildScene('slab', { aspect: 64 / 36 });
      const material = built.subsurface[0];
      material.name = 'see-through skin';
      material.transparent = true;
      material.opacity = 0.5;
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(material);
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.render();
      composer.render();
      const out = await read(renderer, composer.readBuffer);
      sss.dispose();
      composer.dispose();
      return { centre: Array.from(out.slice((18 * 64 + 32) * 4, (18 * 64 + 32) * 4 + 3)) };
    });
    expect(warnings.filter((w) => w.includes('see-through skin'))).toHaveLength(1);
    expect(warnings[0]).toMatch(/transparent = false/);
    expect(Math.min(...r.centre)).toBeGreaterThan(0.1); // drawn, not lost
  });

  it("method 'reference' with a profile other than skin says once that its kernel is skin's", async () => {
    warnings.length = 0;
    await page.evaluate(() => {
      const { SSS, buildScene, DEFAULTS } = window.lab;
      const built = buildScene('slab', { aspect: 1 });
      const make = (options) => new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm, ...options });
      make({ method: 'reference', profile: 'skin' }).dispose(); // Jimenez's own profile: nothing to say
      const sss = make({ method: 'footprint', profile: 'marble' });
      sss.method = 'reference';
      sss.samples = 25; // the same profile again: said already
      sss.method = 'marginal';
      sss.dispose();
    });
    expect(warnings).toHaveLength(1);
    expect(warnings[0]).toMatch(/method 'reference' blurs with Jimenez's built-in skin kernel.*profile 'marble' is used for transmittance only/);
  });
});

describe('no frame recompiles a shader', () => {
  it("'auto' changes its tap count with the on-screen scale without a compile: the program count stays as the first frame left it; the isotropic blur compiles its groups' pair once, on the first frame that draws them", async () => {
    const r = await page.evaluate(() => {
      const { SSS, createRenderer, createComposer, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { aspect: 1 });
      const out = {};
      for (const [key, method, kernelGroups] of [['marginal', 'marginal', 1], ['reference', 'reference', 1], ['footprint', 'footprint', 1], ['isotropic', 'footprint', 'auto']]) {
        const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm, method, samples: 'auto', kernelGroups });
        sss.makeSubsurface(built.subsurface[0], { widthMm: 1 });
        const composer = createComposer(renderer);
        composer.addPass(sss);
        const start = built.camera.position.clone();
        const frames = [];
        // Far to near: the kernel grows on screen, so 'auto' takes more taps frame by frame; the
        // isotropic blur then goes far (one kernel, or no blur) again.
        for (const distance of key === 'isotropic' ? [6, 3, 1.5, 0.8, 0.5, 40] : [6, 3, 1.5, 0.8, 0.5]) {
          built.camera.position.copy(start).multiplyScalar(distance);
          built.camera.updateMatrixWorld();
          composer.render();
          frames.push({ samples: sss.plan.samples, kernelPixels: sss.plan.kernelPixels, groups: sss.plan.groups, blur: sss.plan.blur, programs: renderer.info.programs.length });
        }
        built.camera.position.copy(start);
        out[key] = frames;
        sss.dispose();
        composer.dispose();
      }
      renderer.dispose();
      return out;
    });
    for (const [method, frames] of Object.entries(r)) {
      // The kernel grew on screen over the frames (the test moves the camera in).
      expect(Math.max(...frames.map((f) => f.kernelPixels)), method).toBeGreaterThan(frames[0].kernelPixels * 4);
      // Every frame after the first compiled nothing (the isotropic blur: its groups' two passes, once).
      const bound = frames[0].programs + (method === 'isotropic' ? 2 : 0);
      frames.forEach((frame, i) => {
        expect(frame.programs, `${method}: ${JSON.stringify(frames)}`).toBeLessThanOrEqual(bound);
        expect(frame.programs, `${method}: ${JSON.stringify(frames)}`).toBeGreaterThanOrEqual(frames[Math.max(i - 1, 0)].programs);
      });
    }
    // The fixed-tap methods did change their count (the footprints choose per pixel, the frame keeps 63).
    for (const method of ['marginal', 'reference']) expect(new Set(r[method].map((f) => f.samples)).size, method).toBeGreaterThan(1);
    expect(new Set(r.footprint.map((f) => f.samples))).toEqual(new Set([63]));
    // The isotropic blur drew its groups near and one kernel (or nothing) far, without a compile.
    expect(r.isotropic.at(-2).groups).toBeGreaterThan(1);
    expect(r.isotropic.at(-1).groups === 1 || !r.isotropic.at(-1).blur, JSON.stringify(r.isotropic.at(-1))).toBe(true);
  });
});

describe('other passes before and after it', () => {
  it('with clear = false it keeps an earlier pass where its scene is background and is depth-tested against it; with clear = true it replaces it, like RenderPass', async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { pattern: 'noise', slabSize: 2 });
      // An earlier pass: a red wall far behind, and a green card in front of the slab's right edge.
      const earlier = new THREE.Scene();
      const wall = new THREE.Mesh(new THREE.PlaneGeometry(40, 40), new THREE.MeshBasicMaterial({ color: 0xff0000 }));
      wall.position.z = -5;
      const card = new THREE.Mesh(new THREE.PlaneGeometry(0.6, 0.6), new THREE.MeshBasicMaterial({ color: 0x00ff00 }));
      card.position.set(1, 0, 1);
      earlier.add(wall, card);
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0]);
      const alone = createComposer(renderer);
      alone.addPass(sss);
      alone.render();
      const sssAlone = await read(renderer, alone.readBuffer);
      const earlierAlone = createComposer(renderer);
      earlierAlone.addPass(new RenderPass(earlier, built.camera));
      earlierAlone.render();
      const before = await read(renderer, earlierAlone.readBuffer);

      const composer = createComposer(renderer);
      composer.addPass(new RenderPass(earlier, built.camera));
      composer.addPass(sss);
      composer.render();
      const replaced = await read(renderer, composer.readBuffer);
      sss.clear = false;
      composer.render();
      const kept = await read(renderer, composer.readBuffer);
      const surface = await read(renderer, sss._scenePass.renderTarget, 2);
      sss.dispose();
      for (const c of [alone, earlierAlone, composer]) c.dispose();
      return { sssAlone, before, replaced, kept, surface };
    });
    const onSlab = (i) => r.surface[i * 4 + 1] > 0;
    const green = (i) => r.before[i * 4 + 1] > 0.9;
    expect(maxDifference(r.replaced, r.sssAlone).worst).toBeLessThan(1e-6); // clear = true: as RenderPass
    const background = maxDifference(r.kept, r.before, (i) => !onSlab(i));
    expect(background.count).toBeGreaterThan(5000);
    expect(background.worst).toBeLessThan(1e-6); // the earlier pass kept where the scene drew nothing
    const slab = maxDifference(r.kept, r.sssAlone, (i) => onSlab(i) && !green(i));
    expect(slab.count).toBeGreaterThan(1000);
    expect(slab.worst).toBeLessThan(1e-6); // the slab is nearer than the wall
    const card = maxDifference(r.kept, r.before, (i) => onSlab(i) && green(i));
    expect(card.count).toBeGreaterThan(20);
    expect(card.worst).toBeLessThan(1e-6); // the card is nearer than the slab
  });

  it("leaves the scene's depth in the composer's buffer: a later RenderPass with clearDepth false is hidden behind the skin and seen in front of it", async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { pattern: 'noise', slabSize: 2 });
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0]);
      const later = new THREE.Scene();
      const colour = new THREE.Color(0.2, 0.9, 0.3);
      const inFront = new THREE.Mesh(new THREE.PlaneGeometry(1, 0.5), new THREE.MeshBasicMaterial({ color: colour }));
      inFront.position.set(-1, 0.6, 0.5);
      const behind = new THREE.Mesh(new THREE.PlaneGeometry(1, 0.5), new THREE.MeshBasicMaterial({ color: colour }));
      behind.position.set(1, -0.6, -0.5);
      later.add(inFront, behind);
      const overlay = new RenderPass(later, built.camera);
      overlay.clear = false; // and clearDepth false: test against what is in the buffer
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.render();
      const sssAlone = await read(renderer, composer.readBuffer);
      composer.addPass(overlay);
      composer.render();
      const out = await read(renderer, composer.readBuffer);
      const surface = await read(renderer, sss._scenePass.renderTarget, 2);
      // Where each card covers the screen, from a plain three render of the cards alone.
      const cards = createComposer(renderer);
      cards.addPass(new RenderPass(later, built.camera));
      cards.render();
      const cardsAlone = await read(renderer, cards.readBuffer);
      const hasDepthTexture = sss.depthTexture?.isDepthTexture === true;
      sss.dispose();
      composer.dispose();
      cards.dispose();
      return { out, sssAlone, surface, cardsAlone, colour: colour.toArray(), height: DEFAULTS.height, hasDepthTexture };
    });
    expect(r.hasDepthTexture).toBe(true);
    const row = (i) => Math.floor(i / (r.out.length / 4 / r.height));
    const isCard = (i) => r.cardsAlone[i * 4 + 1] > 0.5;
    const onSlab = (i) => r.surface[i * 4 + 1] > 0;
    const upper = (i) => row(i) > r.height / 2; // GL rows: bottom-up; the front card is in the upper half
    const front = maxDifference(r.out, r.cardsAlone, (i) => isCard(i) && upper(i));
    expect(front.count).toBeGreaterThan(50);
    expect(front.worst).toBeLessThan(1e-3); // drawn over the skin
    const hidden = maxDifference(r.out, r.sssAlone, (i) => isCard(i) && !upper(i) && onSlab(i));
    expect(hidden.count).toBeGreaterThan(50);
    expect(hidden.worst).toBeLessThan(1e-6); // hidden behind it
    const overBackground = maxDifference(r.out, r.cardsAlone, (i) => isCard(i) && !upper(i) && !onSlab(i));
    expect(overBackground.count).toBeGreaterThan(20);
    expect(overBackground.worst).toBeLessThan(1e-3); // seen where no skin is in front
  });

  it('is one pass: insertPass and removePass work, and enabled = false skips it like any pass', async () => {
    const r = await evaluateFloats(page, async () => {
      const { SSS, createRenderer, createComposer, read, buildScene, OutputPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const built = buildScene('slab', { pattern: 'noise', aspect: 64 / 36 });
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0]);
      const added = createComposer(renderer);
      added.addPass(sss);
      added.addPass(new OutputPass());
      added.render();
      const byAdd = await read(renderer, added.readBuffer);
      const inserted = createComposer(renderer);
      inserted.addPass(new OutputPass());
      inserted.insertPass(sss, 0);
      inserted.render();
      const byInsert = await read(renderer, inserted.readBuffer);
      const order = inserted.passes.indexOf(sss);
      inserted.removePass(sss);
      let rendered = 0;
      const render = sss.render.bind(sss);
      sss.render = (...args) => { rendered++; return render(...args); };
      inserted.render();
      added.passes[0].enabled = false;
      added.render();
      sss.dispose();
      added.dispose();
      inserted.dispose();
      return { byAdd, byInsert, order, rendered, passes: inserted.passes.length };
    });
    expect(r.order).toBe(0);
    expect(maxDifference(r.byAdd, r.byInsert).worst).toBe(0);
    expect(r.passes).toBe(1);
    expect(r.rendered).toBe(0); // removed from one composer, disabled in the other
  });

  it('applies its clearColor and clearAlpha to the scene, like RenderPass, and leaves the renderer\'s as they were', async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      renderer.setClearColor(0x000000, 1);
      const built = buildScene('slab', { slabSize: 1, aspect: 64 / 36 });
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0]);
      sss.clearColor = new THREE.Color(0.25, 0.5, 0.75);
      sss.clearAlpha = 0.5;
      const composer = createComposer(renderer);
      composer.addPass(sss);
      composer.render();
      const out = await read(renderer, composer.readBuffer);
      const after = [...renderer.getClearColor(new THREE.Color()).toArray(), renderer.getClearAlpha()];
      sss.dispose();
      composer.dispose();
      return { corner: Array.from(out.slice(0, 4)), after };
    });
    // Linear light, premultiplied by the alpha as three clears a premultiplied-alpha context.
    r.corner.forEach((v, c) => expect(v).toBeCloseTo([0.125, 0.25, 0.375, 0.5][c], 3));
    expect(r.after).toEqual([0, 0, 0, 1]);
  });
});

describe('antialiasing', () => {
  it('with a multisampled composer buffer, silhouettes are antialiased without a halo, and the interior is unchanged', async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { slabSize: 2, intensity: 2 });
      built.scene.children[0].rotation.z = 0.35; // edges at an angle to the pixel grid
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      sss.makeSubsurface(built.subsurface[0], { widthMm: 1 });
      const images = {};
      for (const samples of [0, 4]) {
        const composer = createComposer(renderer, { samples });
        composer.addPass(sss);
        composer.render();
        images[samples] = await read(renderer, composer.readBuffer);
        images[`surface${samples}`] = await read(renderer, sss._scenePass.renderTarget, 2);
        composer.dispose();
      }
      const multisampled = sss._scenePass.renderTarget.samples;
      sss.dispose();
      return { aliased: images[0], antialiased: images[4], surface: images.surface0, multisampled };
    });
    expect(r.multisampled).toBe(4);
    const lum = (img, i) => img[i * 4] + img[i * 4 + 1] + img[i * 4 + 2];
    // The slab's interior level and the background's (black).
    let interior = 0;
    for (let i = 0; i < r.surface.length / 4; i++) if (r.surface[i * 4 + 1] > 0) interior = Math.max(interior, lum(r.aliased, i));
    const partial = (img) => {
      let n = 0;
      for (let i = 0; i < img.length / 4; i++) if (lum(img, i) > 0.05 * interior && lum(img, i) < 0.95 * interior) n++;
      return n;
    };
    const edgeLength = 4 * 2 * (108 / 3.53); // four 2-unit edges at about 31 px per unit
    expect(partial(r.aliased)).toBeLessThan(0.25 * edgeLength); // the blur softens a few, MSAA none
    expect(partial(r.antialiased)).toBeGreaterThan(0.6 * edgeLength);
    // No halo: nothing brighter than the slab's interior, nothing negative.
    for (let i = 0; i < r.antialiased.length / 4; i++) {
      expect(lum(r.antialiased, i)).toBeLessThan(interior * 1.01);
      expect(lum(r.antialiased, i)).toBeGreaterThanOrEqual(0);
    }
    // Two pixels and more inside the silhouette nothing changes.
    const width = 192;
    const deepInside = (i) => {
      const x = i % width;
      const y = Math.floor(i / width);
      for (let dy = -3; dy <= 3; dy++) for (let dx = -3; dx <= 3; dx++) {
        const j = (y + dy) * width + x + dx;
        if (x + dx < 0 || x + dx >= width || j < 0 || j >= r.surface.length / 4 || !(r.surface[j * 4 + 1] > 0)) return false;
      }
      return true;
    };
    const inside = maxDifference(r.antialiased, r.aliased, deepInside);
    expect(inside.count).toBeGreaterThan(2000);
    expect(inside.worst).toBeLessThan(2e-3);
  });
});

describe('an overlay after the pipeline, MSAA 4 (issue 40)', () => {
  it("keeps its antialiased edge along the scene's silhouettes: its coverage per pixel is plain three's (before: 0 or 1 where two RenderPasses blend per sample)", async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, EffectComposer, createRenderer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { slabSize: 2, intensity: 2 });
      built.scene.children[0].rotation.z = 0.35; // edges at an angle to the pixel grid
      // The overlay: an unlit plane behind the slab over the right half of the view, crossing its
      // silhouette: hidden by the slab, seen beside it, per sample along the edge.
      const overlayMaterial = new THREE.MeshBasicMaterial();
      const plane = new THREE.Mesh(new THREE.PlaneGeometry(10, 10), overlayMaterial);
      plane.position.set(5, 0, -1);
      const overlayScene = new THREE.Scene();
      overlayScene.add(plane);
      const frames = async (first, { stencilBuffer = false } = {}) => {
        const buffer = new THREE.WebGLRenderTarget(DEFAULTS.width, DEFAULTS.height, { type: THREE.HalfFloatType, samples: 4, stencilBuffer });
        const composer = new EffectComposer(renderer, buffer);
        composer.renderToScreen = false;
        composer.addPass(first);
        const overlay = new RenderPass(overlayScene, built.camera);
        overlay.clear = false;
        composer.addPass(overlay);
        const out = {};
        for (const [name, colour] of [['white', 1], ['black', 0]]) {
          overlayMaterial.color.setScalar(colour);
          composer.render();
          out[name] = await read(renderer, composer.readBuffer);
        }
        composer.dispose();
        return out;
      };
      const plain = await frames(new RenderPass(built.scene, built.camera));
      // Scattering and transmittance off: the pipeline must draw what plain three draws.
      const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm, scattering: false, transmittance: false });
      sss.makeSubsurface(built.subsurface[0], { widthMm: 1 });
      const pipeline = await frames(sss);
      const handOff = sss._composePass.depthHandOff;
      const problems = [...sss.problems];
      // A buffer with a stencil buffer (another depth format) cannot take the depth per sample: said.
      await frames(sss, { stencilBuffer: true });
      const unlike = [...sss.problems];
      sss.dispose();
      overlayMaterial.dispose();
      plane.geometry.dispose();
      return { plain, pipeline, handOff, problems, unlike };
    });
    // The overlay's coverage of each pixel: white minus black (unlit, linear: the rest cancels).
    const coverage = (f) => Array.from({ length: f.white.length / 4 }, (_, i) => f.white[i * 4] - f.black[i * 4]);
    const plain = coverage(r.plain);
    const pipeline = coverage(r.pipeline);
    const partial = plain.filter((c) => c > 0.1 && c < 0.9).length;
    expect(partial).toBeGreaterThan(20); // plain three's antialiased edge, where the plane meets the slab
    const worst = Math.max(...plain.map((c, i) => Math.abs(c - pipeline[i])));
    expect(worst, `largest coverage difference from plain three: ${worst}`).toBeLessThan(2e-3);
    // Where the overlay covers a pixel fully or not at all, the frame is plain three's.
    const whole = (i) => plain[i] < 1e-3 || plain[i] > 1 - 1e-3;
    expect(maxDifference(r.pipeline.white, r.plain.white, whole).worst).toBeLessThan(2e-3);
    expect(r.handOff).toBe(true); // the output took the split's depth, per sample
    expect(r.problems).toEqual([]);
    expect(r.unlike).toEqual([expect.stringMatching(/^the output buffer is multisampled unlike the scene split \(a depth buffer of format 0x88f0, the scene split 0x81a6 \(a stencil buffer or a depth texture of another type\)\), so the scene's depth is handed on one per pixel/)]);
  });
});

describe('live scene, camera and lights', () => {
  it('a camera switched by assignment renders exactly as a pipeline built with that camera', async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('slab', { pattern: 'noise', slabSize: 3 });
      const other = new THREE.PerspectiveCamera(35, DEFAULTS.width / DEFAULTS.height, 0.05, 200);
      other.position.set(1.5, 0.5, 6);
      other.lookAt(0, 0, 0);
      other.updateMatrixWorld();
      const render = async (camera, build) => {
        const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: build, worldUnitInMm: DEFAULTS.worldUnitInMm });
        sss.makeSubsurface(built.subsurface[0]);
        const composer = createComposer(renderer);
        composer.addPass(sss);
        composer.render();
        sss.camera = camera;
        composer.render();
        const out = await read(renderer, composer.readBuffer);
        sss.dispose();
        composer.dispose();
        return out;
      };
      return { switched: await render(other, built.camera), fresh: await render(other, other), before: await render(built.camera, built.camera) };
    });
    expect(maxDifference(r.switched, r.fresh).worst).toBe(0);
    expect(maxDifference(r.switched, r.before).worst).toBeGreaterThan(0.05); // the view did change
  });

  it('two pipelines share a material independently; disposing one leaves the other unchanged', async () => {
    const r = await evaluateFloats(page, async () => {
      const { SSS, createRenderer, createComposer, read, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
      const built = buildScene('backlit', { thicknessMm: 2 });
      const { scene, camera, light } = built;
      const material = built.subsurface[0];
      const narrow = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: DEFAULTS.worldUnitInMm });
      narrow.makeSubsurface(material, { widthMm: 1 });
      const wide = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
      wide.makeSubsurface(material, { widthMm: 3 });
      const composerA = createComposer(renderer);
      composerA.addPass(narrow);
      const composerB = createComposer(renderer);
      composerB.addPass(wide);
      const frame = async (composer) => { composer.render(); return read(renderer, composer.readBuffer); };
      const a1 = await frame(composerA);
      const b = await frame(composerB);
      const a2 = await frame(composerA);
      wide.dispose();
      const a3 = await frame(composerA);
      const stillHooked = SSS.getSubsurface(material) !== undefined;
      narrow.dispose();
      const unhooked = SSS.getSubsurface(material) === undefined && !material.customProgramCacheKey().includes('subsurface');
      composerA.dispose();
      composerB.dispose();
      return { a1, a2, a3, b, stillHooked, unhooked };
    });
    expect(maxDifference(r.a1, r.a2).worst).toBe(0); // B's frame did not change A's
    expect(maxDifference(r.a1, r.a3).worst).toBe(0); // nor did disposing B
    expect(maxDifference(r.a1, r.b).worst).toBeGreaterThan(0.01); // B has no light: no transmittance
    expect(r.stillHooked).toBe(true);
    expect(r.unhooked).toBe(true);
  });

  it('a light never added to the scene, removed after a frame, or hidden sends no transmittance', async () => {
    const r = await evaluateFloats(page, async () => {
      const { THREE, SSS, createRenderer, createComposer, read, buildScene, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const frame = async (setUp) => {
        const built = buildScene('backlit', { thicknessMm: 1, aspect: 64 / 36 });
        const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: DEFAULTS.worldUnitInMm });
        sss.makeSubsurface(built.subsurface[0]);
        const composer = createComposer(renderer);
        composer.addPass(sss);
        const light = built.light;
        await setUp({ light, scene: built.scene, render: () => composer.render() });
        composer.render();
        const out = await read(renderer, composer.readBuffer, 0);
        const diffuse = await read(renderer, sss._scenePass.renderTarget, 1);
        sss.dispose();
        composer.dispose();
        return { out, diffuse };
      };
      const lit = await frame(() => {});
      const neverAdded = await frame(({ light, scene }) => { scene.remove(light); });
      const removed = await frame(({ light, scene, render }) => { render(); scene.remove(light); });
      const hidden = await frame(({ light }) => { light.visible = false; });
      const parentHidden = await frame(({ light, scene }) => {
        const group = new THREE.Group();
        group.visible = false;
        scene.remove(light);
        group.add(light);
        scene.add(group);
      });
      const offLayer = await frame(({ light }) => { light.layers.set(3); });
      const centre = (img) => Array.from(img.slice((18 * 64 + 32) * 4, (18 * 64 + 32) * 4 + 3));
      return Object.fromEntries(Object.entries({ lit, neverAdded, removed, hidden, parentHidden, offLayer }).map(([k, v]) => [k, centre(v.diffuse)]));
    });
    expect(r.lit[0]).toBeGreaterThan(0.05); // back-lit 1 mm of skin glows red
    for (const name of ['neverAdded', 'removed', 'hidden', 'parentHidden', 'offLayer']) {
      for (const v of r[name]) expect(v, name).toBeLessThan(1e-6);
    }
  });
});

describe('disposal', () => {
  it('a material made subsurface again after its pipeline was disposed renders as the first time, drawn plainly in between or not', async () => {
    const r = await evaluateFloats(page, async () => {
      const { SSS, createRenderer, createComposer, read, buildScene, RenderPass, DEFAULTS } = window.lab;
      const renderer = createRenderer(64, 36);
      const built = buildScene('slab', { pattern: 'noise', aspect: 64 / 36 });
      const material = built.subsurface[0];
      const plain = createComposer(renderer);
      plain.addPass(new RenderPass(built.scene, built.camera));
      const frame = async (composer) => { composer.render(); return read(renderer, composer.readBuffer); };
      const pipeline = async (between) => {
        const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: DEFAULTS.worldUnitInMm });
        sss.makeSubsurface(material);
        const composer = createComposer(renderer);
        composer.addPass(sss);
        const out = await frame(composer);
        const plainWhileHooked = await frame(plain);
        sss.dispose();
        composer.dispose();
        const after = between ? await frame(plain) : null;
        return { out, plainWhileHooked, after };
      };
      const unhooked = await frame(plain);
      const first = await pipeline(true);
      const second = await pipeline(false); // drawn plainly in between (by `first`)
      const third = await pipeline(false); // not drawn in between
      return { unhooked, first, second, third };
    });
    for (const name of ['second', 'third']) {
      expect(maxDifference(r[name].out, r.first.out).worst, name).toBeLessThan(1e-6);
      expect(maxDifference(r[name].plainWhileHooked, r.unhooked).worst, name).toBeLessThan(1e-3);
    }
    expect(maxDifference(r.first.after, r.unhooked).worst).toBeLessThan(1e-6);
  });
});
