// The browser side of the pixel tests: exposes three, the library and the test scenes on
// `window.lab`. `lab.run(options)` builds a scene, renders it through the subsurface pipeline (or a
// plain RenderPass) and returns float read-backs. Nothing here is part of the library.
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import * as SSS from '/test/harness/sss.js';
import * as INTERNALS from '/src/internals.js';
import { ATTACHMENTS } from '/src/2-scene-split/subsurfaceTarget.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { mulberry32 as random } from '/demo/seededRandom.js';
import { dataTexture, flatScene, spheresScene } from './flatScene.js';
import { leafScenes } from './leaves.js';

/** A renderer drawing into an offscreen canvas of `width` × `height` device pixels. */
function createRenderer(width, height, parameters = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias: false, ...parameters });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  return renderer;
}

/** A composer with half-float (or float) buffers (MSAA with `samples`) and no OutputPass: linear HDR out. */
function createComposer(renderer, { type = THREE.HalfFloatType, samples = 0 } = {}) {
  const size = renderer.getDrawingBufferSize(new THREE.Vector2());
  const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(size.x, size.y, { type, samples }));
  composer.renderToScreen = false;
  return composer;
}

/** Reads one attachment of a render target as RGBA floats. */
async function read(renderer, target, index = 0) {
  return readRenderTargetFloats(renderer, target, index);
}


/** Albedo patterns for the slab (texture over the whole slab). */
const PATTERNS = {
  uniform: () => null,
  edgeX: ({ low = 0.05 }) => dataTexture(2, 1, (x) => (x === 0 ? [1, 1, 1] : [low, low, low])),
  edgeY: ({ low = 0.05 }) => dataTexture(1, 2, (x, y) => (y === 0 ? [1, 1, 1] : [low, low, low])),
  point: ({ cells = 255 }) => dataTexture(cells, cells, (x, y) => (x === cells >> 1 && y === cells >> 1 ? [1, 1, 1] : [0, 0, 0])),
  noise: ({ cells = 48, seed = 7 }) => {
    const r = random(seed);
    return dataTexture(cells, cells, () => { const v = 0.1 + 0.9 * r(); return [v, v * 0.8, v * 0.6]; });
  },
  nan: ({ cells = 16 }) => dataTexture(cells, cells, (x, y) => (x === 5 && y === 7 ? [NaN, NaN, NaN] : x === 9 && y === 4 ? [Infinity, 1, 1] : [0.7, 0.5, 0.4])),
};

function camera16x9(aspect, fovY, distance) {
  const camera = new THREE.PerspectiveCamera(fovY, aspect, 0.05, 200);
  camera.position.set(0, 0, distance);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

/** Builds the named scene. Every scene has a front directional light unless it says otherwise. */
const SCENES = {
  /** A flat slab facing the camera filling the view, albedo from `pattern`. */
  slab(o) {
    const scene = new THREE.Scene();
    const camera = camera16x9(o.aspect, o.fovY, o.distance);
    const material = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1, metalness: 0, map: PATTERNS[o.pattern ?? 'uniform'](o) });
    const slab = new THREE.Mesh(new THREE.PlaneGeometry(o.slabSize, o.slabSize), material);
    slab.rotation.y = ((o.tiltDeg ?? 0) * Math.PI) / 180; // seen at a grazing angle
    slab.rotation.x = ((o.tiltXDeg ?? 0) * Math.PI) / 180; // or turned about the horizontal axis
    scene.add(slab);
    const light = new THREE.DirectionalLight(0xffffff, o.intensity);
    light.position.set(0, 0, 10);
    scene.add(light, light.target);
    return { scene, camera, subsurface: [material], light };
  },
  /** A near subsurface slab over the left half, a far subsurface slab `gapWorld` behind it. */
  depthEdge(o) {
    const base = SCENES.slab({ ...o, pattern: 'uniform' });
    const near = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1 });
    base.subsurface[0].color.setScalar(0.02); // the far slab is dark: what leaks onto it shows
    base.subsurface[0].needsUpdate = true;
    const slab = new THREE.Mesh(new THREE.PlaneGeometry(o.slabSize / 2, o.slabSize), near);
    slab.position.set(-o.slabSize / 4, 0, o.gapWorld);
    base.scene.add(slab);
    base.subsurface.push(near);
    return base;
  },
  /** A subsurface slab among ordinary materials: basic, standard, phong, lines; a coloured background. */
  mixed(o) {
    const base = SCENES.slab({ ...o, pattern: 'noise' });
    const { scene } = base;
    scene.background = new THREE.Color(0.2, 0.3, 0.5);
    base.subsurface[0].map.repeat.set(1, 1);
    // The subsurface slab (2 × 1.6 units of a 6.2 × 3.5 view) leaves background around it.
    scene.children[0].scale.set(2 / o.slabSize, 1.6 / o.slabSize, 1);
    const bright = o.brightness ?? 1;
    const basic = new THREE.Mesh(new THREE.BoxGeometry(0.8, 0.8, 0.8), new THREE.MeshBasicMaterial({ color: new THREE.Color(bright, bright * 0.5, 0.1) }));
    basic.position.set(-0.6, 0.1, 0.5);
    const standard = new THREE.Mesh(new THREE.SphereGeometry(0.35, 24, 16), new THREE.MeshStandardMaterial({ color: 0x55aa33, roughness: 0.4 }));
    standard.position.set(1.3, 0.2, 0.3);
    const phong = new THREE.Mesh(new THREE.TorusGeometry(0.3, 0.1, 12, 24), new THREE.MeshPhongMaterial({ color: 0x3366ff, shininess: 60 }));
    phong.position.set(-1.4, -0.2, 0.2);
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(-1.6, -0.6, 0.6), new THREE.Vector3(1.6, 0.6, 0.6)]), new THREE.LineBasicMaterial({ color: 0xffff00 }));
    scene.add(basic, standard, phong, line, new THREE.AmbientLight(0xffffff, 0.3));
    return base;
  },
  /**
   * Two half slabs side by side at the same depth, meeting at x = 0 (the centre column's edge):
   * `sides` = [left, right], each { albedo, pattern (optional), material: makeSubsurface options }
   * or null (left out); `seamShiftWorld` moves both (half a pixel: the seam through a pixel's middle).
   * With `band` (a side too), the halves cover the upper half of the view only and the band the
   * lower half, the whole width, meeting them at y = 0 (a row's edge); it is bound between them
   * (left, band, right: slots 0, 1, 2 when all three profiles differ).
   */
  sideBySide(o) {
    const base = SCENES.slab({ ...o, pattern: 'uniform' });
    base.scene.remove(base.scene.children[0]);
    base.subsurface = [];
    base.subsurfaceOptions = [];
    const height = o.band ? o.slabSize / 2 : o.slabSize;
    const add = (side, width, x, y) => {
      if (!side) return;
      const map = PATTERNS[side.pattern ?? 'uniform'](o);
      const material = new THREE.MeshStandardMaterial({ color: new THREE.Color().setScalar(side.albedo), roughness: 1, metalness: 0, map });
      const piece = new THREE.Mesh(new THREE.PlaneGeometry(width, height), material);
      piece.position.set(x, y, 0);
      base.scene.add(piece);
      base.subsurface.push(material);
      base.subsurfaceOptions.push(side.material ?? {});
    };
    const y = o.band ? o.slabSize / 4 : 0;
    add(o.sides[0], o.slabSize / 2, -o.slabSize / 4 + (o.seamShiftWorld ?? 0), y);
    add(o.band, o.slabSize, 0, -o.slabSize / 4);
    add(o.sides[1], o.slabSize / 2, o.slabSize / 4 + (o.seamShiftWorld ?? 0), y);
    return base;
  },
  /**
   * A slab `thicknessMm` thick, lit from behind, seen from the front (transmittance). With
   * `occluder`, a sheet between the light and the slab's upper right quarter (as the camera sees
   * it) adds `occluderGapMm` to the thickness the light crosses there: a picture that is not
   * symmetric, so a flipped light depth map shows. `fog`: [near, far] of a THREE.Fog; `spot`: a
   * SpotLight in place of the DirectionalLight (below). `sheet`: a plane of no thickness in place of
   * the slab (below).
   */
  backlit(o) {
    const scene = new THREE.Scene();
    const camera = camera16x9(o.aspect, o.fovY, o.distance);
    const material = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1, metalness: 0 });
    const thickness = o.sheet ? 0 : o.thicknessMm / o.worldUnitInMm;
    const slab = new THREE.Mesh(o.sheet ? new THREE.PlaneGeometry(o.slabSize, o.slabSize) : new THREE.BoxGeometry(o.slabSize, o.slabSize, thickness), material);
    if (o.sheet) {
      // A leaf: one plane, both sides drawn, its front face to the light (the camera sees its back
      // face), its upper right quarter (as the camera sees it) cut away by an alpha test.
      slab.rotation.y = Math.PI;
      const alphaMap = dataTexture(2, 2, (x, y) => (x === 0 && y === 1 ? [0, 0, 0] : [1, 1, 1]));
      Object.assign(material, { side: THREE.DoubleSide, alphaMap, alphaTest: 0.5 });
    }
    scene.add(slab);
    if (o.fog) scene.fog = new THREE.Fog(0x3366cc, ...o.fog); // [near, far], world units
    if (o.occluder) {
      const sheet = new THREE.Mesh(new THREE.PlaneGeometry(o.slabSize / 2, o.slabSize / 2), new THREE.MeshStandardMaterial({ side: THREE.DoubleSide }));
      sheet.position.set(o.slabSize / 4, o.slabSize / 4, -thickness / 2 - o.occluderGapMm / o.worldUnitInMm);
      scene.add(sheet);
    }
    // With `spot`, a spot light off the axis (decay 2, its intensity scaled to give the directional
    // light's irradiance at the slab's middle) whose cone edge crosses the view.
    const light = o.spot ? new THREE.SpotLight(0xffffff, o.intensity * 113, 0, Math.PI / 12, 0.5, 2) : new THREE.DirectionalLight(0xffffff, o.intensity);
    // `lightAzimuthDeg`: the directional light turned about y from straight behind (an oblique entry).
    const azimuth = ((o.lightAzimuthDeg ?? 0) * Math.PI) / 180;
    light.position.set(o.spot ? 3 : 10 * Math.sin(azimuth), o.spot ? 2 : 0, -10 * Math.cos(azimuth));
    light.shadow.camera.left = light.shadow.camera.bottom = -o.slabSize;
    light.shadow.camera.right = light.shadow.camera.top = o.slabSize;
    light.shadow.camera.near = 1;
    light.shadow.camera.far = 20;
    scene.add(light, light.target);
    return { scene, camera, subsurface: [material], light, thicknessWorld: thickness };
  },
};

const DEFAULTS = {
  width: 192, height: 108, fovY: 20, distance: 10, slabSize: 20, intensity: Math.PI, occluderGapMm: 1,
  worldUnitInMm: 10, widthMm: 1, pipeline: 'sss', type: 'half', reads: ['output'],
};

/**
 * Builds `options.scene`, renders it once through the pipeline and reads back what `reads` asks for:
 * 'output' (composer result), 'light', 'diffuse', 'surface' (scene pass attachments).
 */
async function run(options) {
  const o = { ...DEFAULTS, ...options };
  o.aspect = o.aspect ?? o.width / o.height;
  const renderer = createRenderer(o.width, o.height);
  const built = SCENES[o.scene](o);
  const type = o.type === 'float' ? THREE.FloatType : THREE.HalfFloatType;
  const composer = createComposer(renderer, { type, samples: o.samples ?? 0 });
  const result = { width: o.width, height: o.height };
  let sss = null;
  if (o.pipeline === 'sss') {
    sss = new SSS.SubsurfaceScattering({
      scene: built.scene, camera: built.camera, worldUnitInMm: o.worldUnitInMm, type,
      light: o.transmittance ? built.light : null,
      ...(o.sss ?? {}),
    });
    built.subsurface.forEach((m, i) => sss.makeSubsurface(m, { widthMm: o.widthMm, ...(o.material ?? {}), ...(built.subsurfaceOptions?.[i] ?? {}) }));
    composer.addPass(sss);
  } else {
    composer.addPass(new RenderPass(built.scene, built.camera));
  }
  if (o.toggleTransmittance) {
    // Off and on again, with the light moved meanwhile: the materials switch programs back and
    // forth (three caches them), and the light's uniforms must follow.
    const home = built.light.position.clone();
    built.light.position.x += 4;
    composer.render();
    sss.transmittance = false;
    composer.render();
    built.light.position.copy(home);
    sss.transmittance = true;
  }
  composer.render();
  const reads = { output: () => read(renderer, composer.readBuffer) };
  if (sss) {
    const t = sss._scenePass.renderTarget;
    const { COLOR, DIFFUSE, SURFACE } = ATTACHMENTS;
    Object.assign(reads, { light: () => read(renderer, t, COLOR), diffuse: () => read(renderer, t, DIFFUSE), surface: () => read(renderer, t, SURFACE) });
    const p = built.camera.projectionMatrix.elements;
    Object.assign(result, {
      kernel: sss._blur.kernel, kernelPixels: sss.plan.kernelPixels, blurEnabled: sss.plan.blur,
      method: sss.method, profile: sss._profileLookup.profile.name,
      footprint: sss._blur.horizontalPass.footprintTable?.table
        ? { table: sss._blur.horizontalPass.footprintTable.table, scales: INTERNALS.FOOTPRINT_SCALES } : undefined,
      projectionScale: [p[0], p[5]], depthThresholdWorld: sss._blur.horizontalPass.depthThresholdWorld,
      thicknessWorld: built.thicknessWorld,
      profileCount: sss._blur.horizontalPass.material.defines.PROFILE_COUNT,
      surfaceChannels: sss._scenePass.surfaceTexture.format === THREE.RGBAFormat ? 4 : 2,
    });
  }
  for (const name of o.reads) result[name] = await reads[name]();
  result.glError = renderer.getContext().getError();
  sss?.dispose();
  composer.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  return result;
}

/**
 * The renderer, pipeline and composer of the last `flat` call, kept while the next one asks for the
 * same pipeline options (resized when its size differs): a new pipeline compiles all its programs
 * again (SwiftShader: 1-3 s a call, most of the accuracy suite's time), while a kept one only swaps
 * its scene and camera, as a user's app does between views. Measured: the same float read-backs to
 * the bit either way. The plane's subsurface material is kept too, its map swapped per call: a
 * newly bound one cost SwiftShader 0.22-0.3 s of GPU-process time a frame (a 256 × 16 strip: 0.25 s
 * a call with a new material, 0.02 s with the kept one; three's program count did not change).
 */
let flatRig = null;

function flatRigFor(width, height, sss) {
  const key = JSON.stringify(sss);
  if (flatRig?.key !== key) {
    disposeFlatRig();
    const renderer = createRenderer(width, height);
    // The scene and camera are each call's (assigned there); these only satisfy the constructor.
    const pipeline = new SSS.SubsurfaceScattering({ scene: new THREE.Scene(), camera: new THREE.OrthographicCamera(), worldUnitInMm: 1, type: THREE.FloatType, ...sss });
    const composer = createComposer(renderer, { type: THREE.FloatType });
    composer.addPass(pipeline);
    flatRig = { key, renderer, pipeline, composer, material: null };
  }
  const { renderer, composer } = flatRig;
  const size = renderer.getDrawingBufferSize(new THREE.Vector2());
  if (size.x !== width || size.y !== height) {
    renderer.setSize(width, height, false);
    composer.setSize(width, height);
  }
  return flatRig;
}

function disposeFlatRig() {
  if (!flatRig) return;
  const { pipeline, composer, renderer, material } = flatRig;
  pipeline.dispose(); // unbinds the kept material first
  material?.dispose();
  composer.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  flatRig = null;
}

/**
 * The analytic accuracy scene (flatScene.js) through the pipeline: returns the diffuse light before
 * the blur and the scattered light after it, float.
 */
async function flat({ width = 256, height = 256, sss = {}, ...scene }) {
  const rig = flatRigFor(width, height, sss);
  const { renderer, pipeline, composer } = rig;
  const { scene: world, camera, material: own, map, plane } = flatScene({ width, height, ...scene });
  // The rig's material (the scene's own settings, made subsurface once) with this call's map.
  if (!rig.material) {
    rig.material = own.clone();
    pipeline.makeSubsurface(rig.material, { widthMm: 1 });
  }
  rig.material.map = map;
  plane.material = rig.material;
  own.dispose();
  Object.assign(pipeline, { scene: world, camera });
  composer.render();
  const before = await read(renderer, pipeline._scenePass.renderTarget, ATTACHMENTS.DIFFUSE);
  const after = await read(renderer, pipeline._blur.scatteredTarget);
  const result = { width, height, before, after, blur: pipeline.plan.blur, glError: renderer.getContext().getError() };
  rig.material.map = null;
  map.dispose();
  plane.geometry.dispose();
  return result;
}

/**
 * The light depth tests' cards (test/browser/1-light-depth/cardDepths.js has what the map holds):
 * a DirectionalLight 10 units up +z looking down (light-space x and y are world x and y, over
 * [−2, 2]²), a back wall at 10 from it and 2 × 2 cards at 7 in three quarters, each with its own
 * shape: upper left cut by its map's alpha, upper right by its alphaMap (offset half a texture),
 * lower left by a clipping plane; lower right glass, a transmissive sheet, a hidden material and
 * points, none of which is a surface to the light. `mapped`: the upper left card.
 */
function lightDepthCards() {
  const scene = new THREE.Scene();
  const light = new THREE.DirectionalLight(0xffffff, 1);
  light.position.set(0, 0, 10); // looking down −z: light-space x and y are world x and y
  Object.assign(light.shadow.camera, { left: -2, right: 2, bottom: -2, top: 2, near: 1, far: 20 });
  scene.add(light, light.target);
  const texel = (rgba) => {
    const t = new THREE.DataTexture(new Uint8Array(rgba), 2, 1);
    t.magFilter = t.minFilter = THREE.NearestFilter;
    t.wrapS = THREE.RepeatWrapping;
    t.needsUpdate = true;
    return t;
  };
  const card = (material, x, y, z) => {
    const mesh = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), material);
    mesh.position.set(x, y, z);
    scene.add(mesh);
    return mesh;
  };
  card(new THREE.MeshStandardMaterial(), 0, 0, 0).scale.set(2, 2, 1); // the back wall, 10 from the light
  // Upper left: alpha from the map, left texel cut away.
  const mapped = card(new THREE.MeshStandardMaterial({ map: texel([255, 255, 255, 0, 255, 255, 255, 255]), alphaTest: 0.5 }), -1, 1, 3);
  // Upper right: alpha from alphaMap (its green for WebGLRenderer, its red for WebGPURenderer's node
  // materials: both alike here), shifted half a texture: the left half reads the cut texel.
  const alphaMap = texel([255, 255, 255, 255, 0, 0, 0, 255]);
  alphaMap.offset.set(0.5, 0);
  card(new THREE.MeshStandardMaterial({ alphaMap, alphaTest: 0.5 }), 1, 1, 3);
  // Lower left: a clipping plane keeps x ≥ −1.
  card(new THREE.MeshStandardMaterial({ clippingPlanes: [new THREE.Plane(new THREE.Vector3(1, 0, 0), 1)] }), -1, -1, 3);
  // Lower right: glass, a transmissive sheet, a hidden material and points: none is a surface here.
  card(new THREE.MeshStandardMaterial({ transparent: true, opacity: 0.3 }), 1, -1, 3);
  card(new THREE.MeshPhysicalMaterial({ transmission: 1 }), 1, -1, 4);
  card(new THREE.MeshStandardMaterial({ visible: false }), 1, -1, 5);
  const points = new THREE.Points(new THREE.PlaneGeometry(2, 2, 32, 32), new THREE.PointsMaterial({ size: 40, sizeAttenuation: false }));
  points.position.set(1, -1, 6);
  scene.add(points);
  // Two small cards turned 60° from the light, in front of the upper ones: the light enters one at
  // cos 60°; the other has no normals, and lets the whole light in.
  const tilted = (x, normals) => {
    const mesh = card(new THREE.MeshStandardMaterial(), x, 0.5, 4);
    mesh.geometry = new THREE.PlaneGeometry(0.6, 0.6);
    if (!normals) mesh.geometry.deleteAttribute('normal');
    mesh.rotation.y = Math.PI / 3;
  };
  tilted(0.5, true);
  tilted(-0.5, false);
  return { scene, light, mapped };
}

/** The cards' depths (cardDepths.js's names) from a 64 × 64 light map, rows bottom-up, `stride` floats a texel. */
function cardDepths(data, stride) {
  const depthAt = (x, y) => data[(Math.floor(((y + 2) / 4) * 64) * 64 + Math.floor(((x + 2) / 4) * 64)) * stride];
  return Object.fromEntries([
    ['mapCut', -1.5, 1.5], ['mapKept', -0.5, 1.5], ['alphaMapCut', 0.5, 1.5], ['alphaMapKept', 1.5, 1.5],
    ['clipped', -1.5, -1.5], ['unclipped', -0.5, -1.5], ['glass', 0.5, -0.5], ['glassToo', 1.5, -1.5],
  ].map(([name, x, y]) => [name, depthAt(x, y)]));
}

/** The entry cosines (cardDepths.js's CARD_COSINES names) from the same map: each texel's second float. */
function cardCosines(data, stride) {
  const at = (x, y) => data[(Math.floor(((y + 2) / 4) * 64) * 64 + Math.floor(((x + 2) / 4) * 64)) * stride + 1];
  return { tilted: at(0.5, 0.5), tiltedNoNormals: at(-0.5, 0.5), unclipped: at(-0.5, -1.5) };
}

/** Builds one of SCENES with the defaults above (aspect from width and height). */
function buildScene(name, options = {}) {
  const o = { ...DEFAULTS, ...options };
  return SCENES[name]({ ...o, aspect: o.aspect ?? o.width / o.height });
}

window.lab = {
  THREE, SSS, EffectComposer, RenderPass, ShaderPass, OutputPass, createRenderer, createComposer, read, dataTexture, run, buildScene, flat, disposeFlatRig, flatScene, spheresScene, DEFAULTS,
  lightDepthCards, cardDepths, cardCosines,
};
Object.assign(window.lab, leafScenes(window.lab));
window.testReady = true;
