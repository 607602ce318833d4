// Transmittance on the GPU (stage 1 light depth + the chunk in the material), against the float64
// oracle: a back-lit slab shows T(d) of its thickness, thick slabs show none, and no acne.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { mat4 } from 'gl-matrix';
import { openPage, runLab } from '../../harness/page.js';
import { at } from '../../harness/images.js';
import { transmittedFractionOracle, thicknessFromLightDepth } from '../../oracle/transmittance.js';
import { CARD_COSINES, CARD_DEPTHS } from './cardDepths.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

const WORLD_UNIT_IN_MM = 10;
const SHRINK_MM = 0.6;

/** The oracle's expectation for the lab's back-lit slab: light straight behind, camera in front. */
function expected(thicknessMm) {
  const half = thicknessMm / WORLD_UNIT_IN_MM / 2;
  // Light at z = −10 looking at the origin: its view matrix, from gl-matrix.
  const lightView = mat4.lookAt(new Float64Array(16), [0, 0, -10], [0, 0, 0], [0, 1, 0]);
  const thicknessWorld = thicknessFromLightDepth({
    lightViewMatrix: lightView,
    pointWorld: [0.3, -0.2, half], // a point on the front face (seen by the camera)
    normalWorld: [0, 0, 1],
    shrinkWorld: SHRINK_MM / WORLD_UNIT_IN_MM,
    mapDepth: () => 10 - half, // the back face is the light's nearest surface
  });
  // Light intensity π straight behind (towards the light: −z in view space), wrap saturate(0.3 + 1)
  // = 1, white albedo: diffuse radiance = the transmitted fraction.
  if (thicknessWorld === Infinity) return [0, 0, 0];
  return transmittedFractionOracle({ thicknessMm: thicknessWorld * WORLD_UNIT_IN_MM, profile: 'skin', shrinkMm: SHRINK_MM, towardLightViewZ: -1 });
}

async function backlit(thicknessMm, lightAzimuthDeg = 0) {
  return runLab(page, {
    scene: 'backlit', thicknessMm, worldUnitInMm: WORLD_UNIT_IN_MM, transmittance: true, type: 'float',
    material: { shrinkMm: SHRINK_MM }, reads: ['diffuse', 'output'], lightAzimuthDeg,
  });
}

/**
 * The oracle for the slab lit from behind at `azimuthDeg` about y: the thickness the light depth
 * map gives, read at the shrunk point (the back face where the ray through it leaves the slab:
 * (d − shrink) / cos a + shrink · cos a, 1.1 mm of the 2 mm chord at 1 mm and 60°); of the light's
 * irradiance cos a enters at the back face (the entry cosine), and the reference's wrap at the exit
 * is saturate(0.3 + cos a) (REFERENCE §5).
 */
function expectedOblique(thicknessMm, azimuthDeg) {
  const a = (azimuthDeg * Math.PI) / 180;
  const half = thicknessMm / WORLD_UNIT_IN_MM / 2;
  if (SHRINK_MM >= thicknessMm) throw new RangeError('expectedOblique: the shrink must stay inside the slab');
  const toLight = [Math.sin(a), 0, -Math.cos(a)];
  const lightView = mat4.lookAt(new Float64Array(16), [10 * toLight[0], 0, 10 * toLight[2]], [0, 0, 0], [0, 1, 0]);
  const point = [0.3, -0.2, half];
  const shrink = SHRINK_MM / WORLD_UNIT_IN_MM;
  const thicknessWorld = thicknessFromLightDepth({
    lightViewMatrix: lightView, pointWorld: point, normalWorld: [0, 0, 1], shrinkWorld: shrink,
    // The back face (z = −half) where the ray from the shrunk point to the light leaves the slab.
    mapDepth: () => {
      const t = (-half - (half - shrink)) / toLight[2];
      const back = [point[0] + t * toLight[0], point[1], -half];
      return -(lightView[2] * back[0] + lightView[6] * back[1] + lightView[10] * back[2] + lightView[14]);
    },
  });
  const through = transmittedFractionOracle({ thicknessMm: thicknessWorld * WORLD_UNIT_IN_MM, profile: 'skin', shrinkMm: SHRINK_MM, towardLightViewZ: toLight[2] });
  return through.map((t) => t * Math.cos(a) * Math.min(1, 0.3 + Math.cos(a)));
}

describe('transmittance', () => {
  it('a back-lit slab 1 mm thick shows the oracle\'s T(d) colour within 2 %, uniformly (no acne)', async () => {
    const r = await backlit(1);
    const t = expected(1);
    expect(t[0]).toBeGreaterThan(0.3); // thin: visibly red
    const { width, height } = r;
    const sums = [0, 0, 0];
    const squares = [0, 0, 0];
    let n = 0;
    for (let y = 20; y < height - 20; y++) for (let x = 30; x < width - 30; x++) {
      const i = at(width, x, y);
      for (let c = 0; c < 3; c++) { sums[c] += r.diffuse[i + c]; squares[c] += r.diffuse[i + c] ** 2; }
      n++;
    }
    for (let c = 0; c < 3; c++) {
      const mean = sums[c] / n;
      const std = Math.sqrt(Math.max(squares[c] / n - mean * mean, 0));
      if (t[c] > 0.01) {
        expect(Math.abs(mean / t[c] - 1), `channel ${c}: GPU ${mean}, oracle ${t[c]}`).toBeLessThan(0.02);
        expect(std / mean, `channel ${c} uniformity`).toBeLessThan(0.01);
      } else {
        expect(Math.abs(mean - t[c])).toBeLessThan(2e-4);
      }
    }
    // Red through, blue stopped: the colour of back-lit skin.
    expect(sums[0]).toBeGreaterThan(5 * sums[2]);
  });

  it('lit at 60° from behind, a 1 mm slab lets in the entry cosine\'s share: T(chord) · cos 60° · wrap, within 2 %', async () => {
    const r = await backlit(1, 60);
    const t = expectedOblique(1, 60);
    // Without the entry cosine it would be twice this.
    expect(t[0]).toBeGreaterThan(0.1);
    const sums = [0, 0, 0];
    let n = 0;
    for (let y = 20; y < r.height - 20; y++) for (let x = 30; x < r.width - 30; x++) {
      for (let c = 0; c < 3; c++) sums[c] += r.diffuse[at(r.width, x, y) + c];
      n++;
    }
    // Red within 2 %. Green and blue fall steeply with the thickness there (T(1.1 mm) about 0.01),
    // and the map's texels, at depths that step across the inclined back face, are averaged in T,
    // which is convex: within 0.005 of the light.
    expect(Math.abs(sums[0] / n / t[0] - 1), `red: GPU ${sums[0] / n}, oracle ${t[0]}`).toBeLessThan(0.02);
    for (const c of [1, 2]) expect(Math.abs(sums[c] / n - t[c]), `channel ${c}: GPU ${sums[c] / n}, oracle ${t[c]}`).toBeLessThan(5e-3);
  });

  it('turned off and on again, transmittance comes back the same', async () => {
    const once = await backlit(1);
    const toggled = await runLab(page, {
      scene: 'backlit', thicknessMm: 1, worldUnitInMm: WORLD_UNIT_IN_MM, transmittance: true, type: 'float',
      material: { shrinkMm: SHRINK_MM }, reads: ['diffuse'], toggleTransmittance: true,
    });
    let worst = 0;
    for (let i = 0; i < once.diffuse.length; i++) worst = Math.max(worst, Math.abs(once.diffuse[i] - toggled.diffuse[i]));
    expect(Math.max(...once.diffuse)).toBeGreaterThan(0.3);
    expect(worst).toBeLessThan(1e-6);
  });

  it('a 50 mm slab transmits nothing (< 1e-3)', async () => {
    const r = await backlit(50);
    expect(Math.max(...expected(50))).toBeLessThan(1e-6);
    let worst = 0;
    for (let y = 10; y < r.height - 10; y++) for (let x = 10; x < r.width - 10; x++) {
      for (let c = 0; c < 3; c++) worst = Math.max(worst, r.diffuse[at(r.width, x, y) + c]);
    }
    expect(worst).toBeLessThan(1e-3);
  });

  it('the light depth target stores linear depth and follows the light', async () => {
    const result = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, read } = window.lab;
      const renderer = createRenderer(16, 16);
      const scene = new THREE.Scene();
      const plane = new THREE.Mesh(new THREE.PlaneGeometry(50, 50), new THREE.MeshBasicMaterial());
      scene.add(plane);
      const light = new THREE.SpotLight(0xffffff, 1, 0, Math.PI / 6);
      light.position.set(0, 0, 7);
      light.shadow.camera.near = 0.5;
      light.shadow.camera.far = 50;
      scene.add(light, light.target);
      const target = new SSS.LightDepthTarget(light, { size: 32 });
      target.render(renderer, scene);
      const first = await read(renderer, target.renderTarget);
      light.position.set(0, 0, 12); // move it
      target.render(renderer, scene);
      const second = await read(renderer, target.renderTarget);
      const centre = (d) => d[(16 * 32 + 16) * 4];
      // The entry cosine beside the depth: at the centre texel and at texel (3, 28).
      const entry = (d, i, j) => d[(j * 32 + i) * 4 + 1];
      const out = { first: centre(first), second: centre(second), cameraZ: target.camera.position.z, fov: target.camera.fov, entryCentre: entry(second, 16, 16), entryCorner: entry(second, 3, 28) };
      target.dispose();
      renderer.dispose();
      return out;
    });
    // Linear distance along the light's axis, in world units: 7, then 12 after the move.
    expect(result.first).toBeCloseTo(7, 4);
    expect(result.second).toBeCloseTo(12, 4);
    expect(result.cameraZ).toBe(12);
    expect(result.fov).toBeCloseTo(60, 6);
    // |N·L| of the plane facing the spot: 1 / sqrt(1 + (x tan 30°)² + (y tan 30°)²) at the texel's NDC (x, y).
    const cosine = (i, j) => {
      const t = Math.tan(Math.PI / 6);
      const [x, y] = [i, j].map((k) => ((k + 0.5) / 32) * 2 - 1);
      return 1 / Math.sqrt(1 + (x * t) ** 2 + (y * t) ** 2);
    };
    expect(result.entryCentre).toBeCloseTo(cosine(16, 16), 3);
    expect(result.entryCorner).toBeCloseTo(cosine(3, 28), 3);
    expect(result.entryCorner).toBeLessThan(0.9);
  });
});

describe('light depth of what the light sees', () => {
  it('follows morph targets, on a mesh and per instance of an InstancedMesh (setMorphAt), as three\'s own depth material does', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, read } = window.lab;
      const renderer = createRenderer(16, 16);
      const scene = new THREE.Scene();
      const light = new THREE.DirectionalLight(0xffffff, 1);
      light.position.set(0, 0, 10); // looking down −z: light-space x and y are world x and y
      Object.assign(light.shadow.camera, { left: -2, right: 2, bottom: -2, top: 2, near: 1, far: 20 });
      scene.add(light, light.target);
      // A unit card whose one morph target moves it 2 towards the light.
      const card = () => {
        const geometry = new THREE.PlaneGeometry(0.8, 0.8);
        const moved = geometry.attributes.position.clone();
        for (let i = 0; i < moved.count; i++) moved.setZ(i, moved.getZ(i) + 2);
        geometry.morphAttributes.position = [moved];
        return geometry;
      };
      const material = new THREE.MeshStandardMaterial();
      const mesh = new THREE.Mesh(card(), material);
      mesh.position.set(0, 1, 0);
      mesh.morphTargetInfluences = [0.5];
      const instanced = new THREE.InstancedMesh(card(), material, 2);
      const at = new THREE.Matrix4();
      instanced.setMatrixAt(0, at.makeTranslation(-1, -1, 0));
      instanced.setMatrixAt(1, at.makeTranslation(1, -1, 0));
      instanced.setMorphAt(0, { morphTargetInfluences: [1] });
      instanced.setMorphAt(1, { morphTargetInfluences: [0] });
      instanced.morphTexture.needsUpdate = true; // as three's instancing-morph example: setMorphAt fills it, the upload is asked for
      scene.add(mesh, instanced);
      const target = new SSS.LightDepthTarget(light, { size: 64 });
      target.render(renderer, scene);
      const data = await read(renderer, target.renderTarget);
      const depthAt = (x, y) => data[(Math.floor(((y + 2) / 4) * 64) * 64 + Math.floor(((x + 2) / 4) * 64)) * 4];
      const gl = renderer.getContext().getError();
      target.dispose();
      renderer.dispose();
      return { mesh: depthAt(0, 1), first: depthAt(-1, -1), second: depthAt(1, -1), gl };
    });
    expect(r.gl).toBe(0);
    expect(r.mesh).toBeCloseTo(9, 4); // half the morph: 1 towards the light
    expect(r.first).toBeCloseTo(8, 4); // instance 0 morphed whole
    expect(r.second).toBeCloseTo(10, 4); // instance 1 not
  });

  it('keeps cut-outs (map or alphaMap alpha test, with the texture\'s offset) and clipping planes, leaves out glass, hidden materials and points, and puts every material back', async () => {
    const r = await page.evaluate(async () => {
      const { SSS, createRenderer, read, lightDepthCards, cardDepths, cardCosines } = window.lab;
      const renderer = createRenderer(16, 16);
      renderer.localClippingEnabled = true;
      const { scene, light, mapped } = lightDepthCards();
      const before = [];
      scene.traverse((o) => { if (o.material) before.push(o.material); });

      const target = new SSS.LightDepthTarget(light, { size: 64 });
      target.render(renderer, scene);
      const data = await read(renderer, target.renderTarget);
      const after = [];
      scene.traverse((o) => { if (o.material) after.push(o.material); });
      const samples = cardDepths(data, 4);
      const cosines = cardCosines(data, 4);
      const variants = target._shaped.size;
      mapped.material.dispose();
      const afterOneDisposed = target._shaped.size;
      target.dispose();
      renderer.dispose();
      return { samples, cosines, same: before.length === after.length && before.every((m, i) => m === after[i]), variants, afterOneDisposed, left: target._shaped.size };
    });
    // Distances along the light's axis (version 0.1 drew every card whole: 7 everywhere above, 4 below right).
    for (const [name, depth] of Object.entries(CARD_DEPTHS)) expect(r.samples[name], name).toBeCloseTo(depth, 4);
    for (const [name, cosine] of Object.entries(CARD_COSINES)) expect(r.cosines[name], name).toBeCloseTo(cosine, 3);
    expect(r.same).toBe(true);
    expect(r.variants).toBe(3); // one depth material per cut-out or clipped material, the rest share one
    expect(r.afterOneDisposed).toBe(2);
    expect(r.left).toBe(0);
  });
});

describe('transmittance artifacts', () => {
  it('a front or side light adds nothing through a thick sphere: no band along the terminator (version 0.1: 2 % of the lit level)', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, createComposer, read } = window.lab;
      const renderer = createRenderer(128, 128);
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 10);
      camera.position.set(0, 0, 0.4);
      const skin = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.6 });
      scene.add(new THREE.Mesh(new THREE.SphereGeometry(0.08, 96, 64), skin));
      const out = {};
      for (const [name, direction] of [['front-side', [1, 0.2, 0.6]], ['side', [1, 0.2, 0]]]) {
        const light = new THREE.DirectionalLight(0xffffff, Math.PI);
        light.position.set(...direction.map((v) => v * 0.5));
        Object.assign(light.shadow.camera, { left: -0.12, bottom: -0.12, right: 0.12, top: 0.12, near: 0.01, far: 2 });
        scene.add(light, light.target);
        const sss = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
        sss.makeSubsurface(skin);
        const composer = createComposer(renderer, { type: THREE.FloatType });
        composer.addPass(sss);
        composer.render();
        const on = await read(renderer, sss._scenePass.renderTarget, 1);
        sss.transmittance = false;
        composer.render();
        const off = await read(renderer, sss._scenePass.renderTarget, 1);
        let added = 0;
        let lit = 0;
        for (let i = 0; i < on.length; i += 4) for (let c = 0; c < 3; c++) { added = Math.max(added, on[i + c] - off[i + c]); lit = Math.max(lit, off[i + c]); }
        out[name] = added / lit;
        sss.dispose();
        composer.dispose();
        scene.remove(light, light.target);
      }
      return out;
    });
    expect(r['front-side']).toBeLessThan(1e-3);
    expect(r.side).toBeLessThan(1e-3);
  });

  it('a light on the camera\'s side of every subsurface mesh skips the light depth pass and changes nothing; behind a mesh the pass runs, and moving back and forth leaves no stale map', async () => {
    const r = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, createComposer, read } = window.lab;
      const renderer = createRenderer(64, 64);
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 10);
      camera.position.set(0, 0, 0.4);
      const skin = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.6 });
      const slab = new THREE.Mesh(new THREE.BoxGeometry(0.2, 0.2, 0.002), skin); // 2 mm: light comes through
      scene.add(slab);
      const light = new THREE.SpotLight(0xffffff, 20, 0, Math.PI / 6, 0, 0);
      Object.assign(light.shadow.camera, { near: 0.05, far: 2 });
      scene.add(light, light.target);
      const sss = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
      sss.makeSubsurface(skin);
      const composer = createComposer(renderer, { type: THREE.FloatType });
      composer.addPass(sss);
      let stages = [];
      sss.stageTimer = { begin: (stage) => stages.push(stage), end: () => {} };
      // The slab's front face is 1 mm in front of z = 0: a light at z ≥ 0.001 is on the camera's side of all of it.
      const frame = async (z, transmittance = true) => {
        light.position.set(0.05, 0.02, z);
        sss.transmittance = transmittance;
        stages = [];
        composer.render();
        return { diffuse: await read(renderer, sss._scenePass.renderTarget, 1), lightDepth: stages.includes('lightDepth') };
      };
      const worst = (a, b) => a.diffuse.reduce((m, v, i) => Math.max(m, Math.abs(v - b.diffuse[i])), 0);
      const brightest = (a) => Math.max(...a.diffuse.filter((_, i) => i % 4 !== 3));
      const behind = await frame(-0.3);
      const behindOff = await frame(-0.3, false);
      const front = await frame(0.3);
      const frontOff = await frame(0.3, false);
      const grazing = await frame(0.0011); // just in front of the front face
      const behindAgain = await frame(-0.3);
      sss.debugView = 'thickness';
      const thickness = await frame(0.3);
      sss.dispose();
      composer.dispose();
      return {
        behindPass: behind.lightDepth, frontPass: front.lightDepth, grazingPass: grazing.lightDepth, thicknessPass: thickness.lightDepth,
        glow: brightest(behind) - brightest(behindOff), frontChange: worst(front, frontOff), backAgain: worst(behind, behindAgain),
        grazingLit: brightest(grazing), thicknessMax: brightest(thickness),
      };
    });
    expect(r.behindPass).toBe(true);
    expect(r.glow).toBeGreaterThan(0.05); // 2 mm of skin lets red through
    expect(r.frontPass).toBe(false);
    expect(r.frontChange).toBe(0); // the model sends no light from the camera's side: exactly as without transmittance
    expect(r.grazingPass).toBe(false);
    expect(r.grazingLit).toBeGreaterThan(0); // the slab is still lit from the front
    expect(r.backAgain).toBe(0); // the map skipped in between is rendered again, not read stale
    expect(r.thicknessPass).toBe(true); // the thickness view reads the map whatever the light
    expect(r.thicknessMax).toBeGreaterThan(0);
  });

  it('with a wide spot cone (36°) behind the head, no single lit pixels: the light map is read with bilinear weights (version 0.1: about 100)', async () => {
    const demo = await openPage('/?still', { width: 640, height: 360 });
    const r = await demo.evaluate(async () => {
      const d = window.demo;
      d.stop();
      d.rig.light.angle = (36 * Math.PI) / 180;
      d.set('lightAzimuth', 160);
      d.set('view', 'transmittance');
      const { width: W, height: H, data } = await d.readHdr();
      const L = (i) => data[i * 4] + data[i * 4 + 1] + data[i * 4 + 2];
      let isolated = 0;
      let lit = 0;
      for (let y = 1; y < H - 1; y++) {
        for (let x = 1; x < W - 1; x++) {
          const i = y * W + x;
          const v = L(i);
          if (v > 0.01) lit++;
          // Lit on its own: brighter than 4 × its second-brightest neighbour.
          const around = [L(i - 1), L(i + 1), L(i - W), L(i + W), L(i - W - 1), L(i - W + 1), L(i + W - 1), L(i + W + 1)].sort((a, b) => a - b);
          if (v > 0.05 && v > 4 * around[6] + 0.02) isolated++;
        }
      }
      return { isolated, lit, standIn: d.isStandIn };
    });
    expect(demo.problems).toEqual([]);
    await demo.close();
    expect(r.lit).toBeGreaterThan(100); // the rims do glow
    expect(r.isolated).toBeLessThanOrEqual(5);
  });
});
