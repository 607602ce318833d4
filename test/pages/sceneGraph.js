// The browser side of test/browser/sceneGraph.test.js: three's scene graph, feature by feature.
// Each row builds a scene that uses one feature (`feature`) and, where the row has one, the same
// picture drawn without it (`reference`: separate meshes for an InstancedMesh, the baked shape for
// morph targets, layer 0 for layer 1...), then renders through a RenderPass and through the
// pipeline, off (no scattering, no transmittance) and on, and reports the differences, the draw
// calls and the light depth passes. The test file holds the assertions. The WebGPU node's rows
// (test/pages/webgpu.js's sceneGraphRow) draw these scenes too.
import './lab.js';

const { THREE, SSS, RenderPass, createComposer, read } = window.lab;
export const WIDTH = 96;
export const HEIGHT = 64;
/** Millimetres of material per profile mm: the 24 cm slab's texture edges blur over several pixels at 96 × 64. */
export const WIDTH_MM = 40;

/** Stripes along x (nearest-filtered), so scattering shows at their edges. */
function stripes() {
  const data = new Uint8Array(8 * 4);
  for (let x = 0; x < 8; x++) data.set(x % 2 ? [250, 230, 210, 255] : [60, 30, 25, 255], 4 * x);
  const texture = new THREE.DataTexture(data, 8, 1);
  Object.assign(texture, { colorSpace: THREE.SRGBColorSpace, magFilter: THREE.NearestFilter, minFilter: THREE.NearestFilter, needsUpdate: true });
  return texture;
}

/** The subsurface material of a row (one per scene unless the row shares it). */
const skin = () => new THREE.MeshStandardMaterial({ map: stripes(), roughness: 0.8, name: 'skin' });

/** A 24 cm slab 2 mm thick facing the camera (its shape for the rows that change geometry). */
const slabGeometry = () => new THREE.BoxGeometry(0.24, 0.24, 0.002);

/**
 * The scene every row starts from: the camera 1 m in front of the origin, a spot light behind the
 * slab's place (it transmits through it), a front light, an ordinary floor and boxes around (none
 * between the spot light and the slab), and `add(scene)`'s subsurface meshes.
 */
function baseScene(add, { fog = null, ordinary = true } = {}) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x101418);
  scene.fog = fog;
  const camera = new THREE.PerspectiveCamera(30, WIDTH / HEIGHT, 0.05, 20);
  camera.position.set(0, 0, 1);
  camera.lookAt(0, 0, 0);
  const light = new THREE.SpotLight(0xffffff, 40, 0, Math.PI / 10, 0.2, 2);
  light.position.set(0.25, 0.15, -1);
  light.target.position.set(0, 0, 0);
  const front = new THREE.DirectionalLight(0xffffff, 1.5);
  front.position.set(-1, 1, 2);
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(1.2, 1.2), new THREE.MeshStandardMaterial({ color: 0x607080 }));
  floor.rotation.x = -Math.PI / 2;
  floor.position.y = -0.3;
  scene.add(light, light.target, front, new THREE.AmbientLight(0xffffff, 0.3));
  if (ordinary) scene.add(floor);
  for (let i = 0; ordinary && i < 6; i++) {
    const box = new THREE.Mesh(new THREE.BoxGeometry(0.06, 0.06, 0.06), new THREE.MeshStandardMaterial({ color: 0x3070c0 }));
    box.position.set(-0.3 + 0.12 * i, -0.22, 0.25);
    scene.add(box);
  }
  const subsurface = add(scene) ?? [];
  scene.updateMatrixWorld();
  return { scene, camera, light, subsurface };
}

/** One slab at `x`, `y` (metres) with `material`, added to `parent`. */
function slab(parent, material, x = 0, y = 0, geometry = slabGeometry()) {
  const mesh = new THREE.Mesh(geometry, material);
  mesh.position.set(x, y, 0);
  parent.add(mesh);
  return mesh;
}

/** The materials of `scene`'s meshes that `isSkin` picks (the ones a row makes subsurface). */
function skinMaterials(scene) {
  const found = new Set();
  scene.traverse((object) => {
    for (const m of Array.isArray(object.material) ? object.material : [object.material]) if (m?.name === 'skin') found.add(m);
  });
  return [...found];
}

/**
 * Renders `built` (baseScene's) once through `pass` ('plain': three's RenderPass; 'off' or 'on':
 * the pipeline) on `renderer`, after a first frame (compiles, fits), and returns the read-back,
 * the draw calls of the frame and of its light depth passes, and what the pipeline said.
 */
async function frame(renderer, built, pass, { frames = 2, pipelineOptions = {}, composerOptions = {}, before } = {}) {
  const { scene, camera, light } = built;
  const composer = createComposer(renderer, composerOptions);
  let sss = null;
  if (pass === 'plain') {
    composer.addPass(new RenderPass(scene, camera));
  } else {
    const on = pass === 'on';
    sss = new SSS.SubsurfaceScattering({
      scene, camera, light, worldUnitInMm: 1000, lightDepthSize: 256, scattering: on, transmittance: on, ...pipelineOptions,
    });
    for (const material of skinMaterials(scene)) sss.makeSubsurface(material, { widthMm: WIDTH_MM });
    composer.addPass(sss);
  }
  const info = renderer.info;
  info.autoReset = false;
  let lightCalls = 0;
  let lightPasses = 0;
  if (sss) {
    let start = 0;
    sss.stageTimer = {
      begin(stage) { if (stage === 'lightDepth') start = info.render.calls; },
      end(stage) { if (stage === 'lightDepth') { lightCalls += info.render.calls - start; lightPasses++; } },
    };
  }
  for (let i = 0; i < frames; i++) {
    before?.(i);
    info.reset();
    lightCalls = 0;
    lightPasses = 0;
    composer.render();
  }
  const calls = info.render.calls;
  info.autoReset = true;
  const pixels = await read(renderer, composer.readBuffer);
  const result = {
    pixels, calls, lightCalls, lightPasses, glError: renderer.getContext().getError(),
    problems: sss ? [...sss.problems] : [], plan: sss ? { ...sss.plan } : null, subsurfaceOnScreen: sss ? sss._scenePass.subsurfaceMeshes.length : 0,
  };
  sss?.dispose();
  composer.dispose();
  return result;
}

/**
 * The largest difference of any channel, how many pixels differ by more than `over` (rgb, the
 * first few of them in `where`: x, y from the bottom, a's and b's red), and b's largest value.
 */
export function compare(a, b, over = 0.01) {
  let worst = 0;
  let differing = 0;
  let nonFinite = 0;
  let level = 0;
  const where = [];
  for (let i = 0; i < a.length; i += 4) {
    let pixel = 0;
    for (let c = 0; c < 3; c++) {
      if (!Number.isFinite(a[i + c]) || !Number.isFinite(b[i + c])) nonFinite++;
      pixel = Math.max(pixel, Math.abs(a[i + c] - b[i + c]));
      level = Math.max(level, Math.abs(b[i + c]));
    }
    worst = Math.max(worst, pixel);
    if (pixel > over) { differing++; if (where.length < 30) where.push([(i / 4) % WIDTH, Math.floor(i / 4 / WIDTH), +a[i].toFixed(3), +b[i].toFixed(3)]); }
  }
  return { worst, differing, nonFinite, level, where };
}

function createRenderer(parameters = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias: false, ...parameters });
  renderer.setPixelRatio(1);
  renderer.setSize(WIDTH, HEIGHT, false);
  return renderer;
}

/**
 * Runs the row's frames: `feature` through the RenderPass and the pipeline off and on, and
 * `reference` (when given) through the pipeline on; returns their comparisons.
 */
async function compareRow({ feature, reference, renderer: rendererParameters, frameOptions = {}, referenceOptions = frameOptions }) {
  const renderer = createRenderer(rendererParameters);
  const warnings = [];
  const warn = console.warn;
  console.warn = (...args) => { warnings.push(args.join(' ')); warn.apply(console, args); };
  try {
    const plain = await frame(renderer, feature(), 'plain', frameOptions);
    const off = await frame(renderer, feature(), 'off', frameOptions);
    const on = await frame(renderer, feature(), 'on', frameOptions);
    const ref = reference ? await frame(renderer, reference(), 'on', referenceOptions) : null;
    const strip = ({ pixels, ...rest }) => rest;
    return {
      offVsPlain: compare(off.pixels, plain.pixels),
      onVsReference: ref ? compare(on.pixels, ref.pixels) : null,
      onVsOff: compare(on.pixels, off.pixels),
      plain: strip(plain), off: strip(off), on: strip(on), reference: ref ? strip(ref) : null,
      warnings,
    };
  } finally {
    console.warn = warn;
    renderer.dispose();
    renderer.forceContextLoss();
  }
}

/** An alpha map (three reads its green) of 1 on the left half and 0 on the right (nearest). */
function leftHalf() {
  const texture = new THREE.DataTexture(new Uint8Array([255, 255, 255, 255, 0, 0, 0, 0]), 2, 1);
  Object.assign(texture, { magFilter: THREE.NearestFilter, minFilter: THREE.NearestFilter, needsUpdate: true });
  return texture;
}

/** The left half of the 24 cm plane, with that half's uvs (the cut-out rows' reference). */
function leftHalfPlane() {
  const geometry = new THREE.PlaneGeometry(0.12, 0.24);
  const uv = geometry.attributes.uv;
  for (let i = 0; i < uv.count; i++) uv.setX(i, 0.5 * uv.getX(i));
  return geometry;
}

/** The rows: each a feature scene and, where it has one, the reference drawn without the feature. */
export const ROWS = {
  /** A hidden subsurface mesh, and one under a hidden parent: the frame is three's plain frame. */
  visible: {
    feature: () => baseScene((scene) => {
      slab(scene, skin()).visible = false;
      const parent = new THREE.Group();
      parent.visible = false;
      scene.add(parent);
      slab(parent, skin(), 0.1);
    }),
  },
  /** A subsurface mesh behind the camera. */
  behindCamera: { feature: () => baseScene((scene) => { slab(scene, skin()).position.z = 2; }) },
  /** The camera turned away from the subsurface mesh. */
  turnedAway: {
    feature: () => {
      const built = baseScene((scene) => { slab(scene, skin()); });
      built.camera.lookAt(0, 0, 2);
      return built;
    },
  },
  /** frustumCulled false on the on-screen mesh: as culled. */
  frustumCulledFalse: {
    feature: () => baseScene((scene) => { slab(scene, skin()).frustumCulled = false; }),
    reference: () => baseScene((scene) => { slab(scene, skin()); }),
  },
  /** The subsurface mesh on layer 1 of a camera that sees 0 and 1: as on layer 0 (transmittance too). */
  cameraLayers: {
    feature: () => {
      const built = baseScene((scene) => { slab(scene, skin()).layers.set(1); });
      built.camera.layers.enable(1);
      return built;
    },
    reference: () => baseScene((scene) => { slab(scene, skin()); }),
  },
  /** The light's shadow camera on layer 2 only: its pass sees nothing on 0 (three's shadow rule), so nothing transmits. */
  lightLayers: {
    feature: () => {
      const built = baseScene((scene) => { slab(scene, skin()); });
      built.light.shadow.camera.layers.set(2);
      return built;
    },
    reference: () => baseScene((scene) => { slab(scene, skin()); }),
    referenceOptions: { pipelineOptions: { transmittance: false } },
  },
  /** renderOrder reversed: the opaque image is the depth test's. */
  renderOrder: {
    feature: () => baseScene((scene) => {
      const near = slab(scene, skin(), -0.05);
      near.position.z = 0.05;
      near.renderOrder = 2;
      slab(scene, skin(), 0.05).renderOrder = 1;
      scene.children.forEach((child, i) => { if (!child.material?.name) child.renderOrder = -i; });
    }),
    reference: () => baseScene((scene) => {
      slab(scene, skin(), -0.05).position.z = 0.05;
      slab(scene, skin(), 0.05);
    }),
  },
  /** Three slabs as one InstancedMesh with a colour each: as three meshes. */
  instancedMesh: {
    feature: () => baseScene((scene) => {
      const mesh = new THREE.InstancedMesh(slabGeometry(), skin(), 3);
      const colours = [0xffffff, 0xffaa88, 0x88ccff];
      for (let i = 0; i < 3; i++) {
        mesh.setMatrixAt(i, new THREE.Matrix4().makeTranslation(-0.09 + 0.09 * i, 0.03 * i, 0));
        mesh.setColorAt(i, new THREE.Color(colours[i]));
      }
      mesh.scale.setScalar(0.5);
      scene.add(mesh);
    }),
    reference: () => baseScene((scene) => {
      const colours = [0xffffff, 0xffaa88, 0x88ccff];
      for (let i = 0; i < 3; i++) {
        const material = skin();
        material.color.set(colours[i]);
        const mesh = slab(scene, material, 0.5 * (-0.09 + 0.09 * i), 0.5 * 0.03 * i);
        mesh.scale.setScalar(0.5);
      }
    }),
  },
  /** Two slabs as one BatchedMesh: as two meshes. */
  batchedMesh: {
    feature: () => baseScene((scene) => {
      const mesh = new THREE.BatchedMesh(2, 64, 64, skin());
      const geometry = mesh.addGeometry(slabGeometry());
      for (const x of [-0.07, 0.07]) mesh.setMatrixAt(mesh.addInstance(geometry), new THREE.Matrix4().makeTranslation(x, 0, 0));
      scene.add(mesh);
    }),
    reference: () => baseScene((scene) => {
      const material = skin();
      for (const x of [-0.07, 0.07]) slab(scene, material, x);
    }),
  },
  /** A slab bent by a morph target at 0.7: as the same shape baked. */
  morphTargets: {
    feature: () => baseScene((scene) => {
      const geometry = slabGeometry();
      const bent = geometry.attributes.position.clone();
      for (let i = 0; i < bent.count; i++) bent.setZ(i, bent.getZ(i) + 0.2 * bent.getX(i) ** 2);
      geometry.morphAttributes.position = [bent];
      const mesh = slab(scene, skin(), 0, 0, geometry);
      mesh.updateMorphTargets();
      mesh.morphTargetInfluences[0] = 0.7;
    }),
    reference: () => baseScene((scene) => {
      const geometry = slabGeometry();
      const position = geometry.attributes.position;
      for (let i = 0; i < position.count; i++) position.setZ(i, position.getZ(i) + 0.7 * 0.2 * position.getX(i) ** 2);
      geometry.computeBoundingBox();
      slab(scene, skin(), 0, 0, geometry);
    }),
  },
  /** A skinned slab, its bone turned: as the posed shape baked. */
  skinning: {
    feature: () => baseScene((scene) => {
      const geometry = slabGeometry();
      const count = geometry.attributes.position.count;
      geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(new Array(count * 4).fill(0), 4));
      geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(Array.from({ length: count * 4 }, (_, i) => (i % 4 === 0 ? 1 : 0)), 4));
      const bone = new THREE.Bone();
      const mesh = new THREE.SkinnedMesh(geometry, skin());
      mesh.add(bone);
      mesh.bind(new THREE.Skeleton([bone]));
      bone.rotation.y = 0.5;
      bone.position.x = 0.03;
      scene.add(mesh);
    }),
    reference: () => baseScene((scene) => {
      const mesh = slab(scene, skin());
      mesh.rotation.y = 0.5;
      mesh.position.x = 0.03;
    }),
  },
  /** A subsurface mesh and its clone (Object3D.clone: one material shared): as two meshes of one material. */
  clones: {
    feature: () => baseScene((scene) => {
      const mesh = slab(scene, skin(), -0.07);
      const copy = mesh.clone();
      copy.position.x = 0.07;
      scene.add(copy);
    }),
    reference: () => baseScene((scene) => {
      const material = skin();
      slab(scene, material, -0.07);
      slab(scene, material, 0.07);
    }),
  },
  /** A cut-out (alphaTest) of the slab's right half: as a slab of half the width (the light sees the cut too). */
  alphaTest: {
    feature: () => baseScene((scene) => {
      const material = skin();
      Object.assign(material, { alphaMap: leftHalf(), alphaTest: 0.5 });
      slab(scene, material, 0, 0, new THREE.PlaneGeometry(0.24, 0.24)).material.side = THREE.DoubleSide;
    }),
    reference: () => baseScene((scene) => {
      slab(scene, skin(), -0.06, 0, leftHalfPlane()).material.side = THREE.DoubleSide;
    }),
  },
  /** The same cut-out by alphaHash (alpha 0 or 1: the hash keeps what the test keeps). */
  alphaHash: {
    feature: () => baseScene((scene) => {
      const material = skin();
      Object.assign(material, { alphaMap: leftHalf(), alphaHash: true, side: THREE.DoubleSide });
      slab(scene, material, 0, 0, new THREE.PlaneGeometry(0.24, 0.24));
    }),
    reference: () => baseScene((scene) => {
      slab(scene, skin(), -0.06, 0, leftHalfPlane()).material.side = THREE.DoubleSide;
    }),
  },
  /** side: DoubleSide on the slab (its back faces drawn, hidden by its front ones): as FrontSide. */
  side: {
    feature: () => baseScene((scene) => {
      const material = skin();
      material.side = THREE.DoubleSide;
      slab(scene, material);
    }),
    reference: () => baseScene((scene) => { slab(scene, skin()); }),
  },
  /** A transparent subsurface material: drawn as three draws it (blended, unscattered), said once. */
  transparent: {
    feature: () => baseScene((scene) => {
      const material = skin();
      Object.assign(material, { transparent: true, opacity: 0.6 });
      slab(scene, material);
    }),
  },
  /** The camera near one LOD level, the light in another's range: the camera's level, with transmittance, no GL error. */
  lod: {
    feature: () => baseScene((scene) => {
      const lod = new THREE.LOD();
      lod.addLevel(slab(new THREE.Group(), skin()), 0);
      const coarse = new THREE.MeshStandardMaterial({ color: 0x00ff00, name: 'skin' });
      lod.addLevel(new THREE.Mesh(new THREE.BoxGeometry(0.24, 0.24, 0.002), coarse), 1.02); // the camera is 1 m away, the light 1.04 m
      scene.add(lod);
    }),
    reference: () => baseScene((scene) => { slab(scene, skin()); }),
  },
  /** Fog: off, as three; on, the scattered frame fogged as three fogs (a slab at one depth: one factor). */
  fog: {
    feature: () => baseScene((scene) => { slab(scene, skin()); }, { fog: new THREE.Fog(0x101418, 0.5, 1.6) }),
    reference: () => baseScene((scene) => { slab(scene, skin()); }),
  },
};

/** An orthographic camera of the perspective camera's scale at the slab (1 m away). */
function orthographic(built) {
  const half = Math.tan((15 * Math.PI) / 180);
  const camera = new THREE.OrthographicCamera(-half * (WIDTH / HEIGHT), half * (WIDTH / HEIGHT), half, -half, 0.05, 20);
  camera.position.set(0, 0, 1);
  camera.lookAt(0, 0, 0);
  return { ...built, camera };
}

/** A perspective camera 40 m away with the field that gives it the same scale: nearly orthographic. */
function farPerspective(built) {
  const camera = new THREE.PerspectiveCamera((2 * Math.atan(Math.tan((15 * Math.PI) / 180) / 40) * 180) / Math.PI, WIDTH / HEIGHT, 30, 50);
  camera.position.set(0, 0, 40);
  camera.lookAt(0, 0, 0);
  return { ...built, camera };
}

Object.assign(ROWS, {
  /** An orthographic camera: as a perspective camera so far away it barely converges, at the same scale. */
  orthographicCamera: {
    feature: () => orthographic(baseScene((scene) => { slab(scene, skin()); }, { ordinary: false })),
    reference: () => farPerspective(baseScene((scene) => { slab(scene, skin()); }, { ordinary: false })),
  },
  /** A logarithmic depth buffer: as the plain depth buffer. */
  logarithmicDepth: {
    renderer: { logarithmicDepthBuffer: true },
    feature: () => baseScene((scene) => { slab(scene, skin()); }),
    reference: 'plainRenderer',
  },
  /** A reversed depth buffer (three r180+, where the device has EXT_clip_control): as the plain one. */
  reversedDepth: {
    renderer: { reversedDepthBuffer: true },
    feature: () => baseScene((scene) => { slab(scene, skin()); }),
    reference: 'plainRenderer',
  },
});

/** Runs row `name` (see ROWS); a reference of 'plainRenderer' is the feature scene on a renderer without the row's parameters. */
async function row(name, options) {
  const spec = { ...ROWS[name], ...options };
  if (spec.reference !== 'plainRenderer') return compareRow(spec);
  const result = await compareRow({ ...spec, reference: null });
  const renderer = createRenderer();
  try {
    const ref = await frame(renderer, spec.feature(), 'on');
    const onAgain = await frame((result.renderer = createRenderer(spec.renderer)), spec.feature(), 'on');
    result.onVsReference = compare(onAgain.pixels, ref.pixels);
    result.renderer.dispose();
    result.renderer.forceContextLoss();
    delete result.renderer;
    return result;
  } finally {
    renderer.dispose();
    renderer.forceContextLoss();
  }
}

/** Fog's closed form: three's Fog factor at view depth `depth`, smoothstep(near, far, depth) (fog_fragment.glsl). */
function fogFactor(fog, depth) {
  const t = Math.min(Math.max((depth - fog.near) / (fog.far - fog.near), 0), 1);
  return t * t * (3 - 2 * t);
}

/**
 * The fog row's check: the fogged scattered frame against the unfogged one mixed towards the fog
 * colour by the fog factor at the slab (one depth), over the slab's pixels.
 */
async function fogRow() {
  const renderer = createRenderer();
  try {
    const fogged = ROWS.fog.feature();
    const on = await frame(renderer, fogged, 'on');
    const clear = await frame(renderer, ROWS.fog.reference(), 'on');
    const mask = await frame(renderer, ROWS.fog.reference(), 'on', { pipelineOptions: { debugView: 'mask' } });
    const f = fogFactor(fogged.scene.fog, 1 - 0.001); // the slab's front face, 1 mm before the origin
    const colour = fogged.scene.fog.color;
    let worst = 0;
    let compared = 0;
    let level = 0;
    for (let i = 0; i < on.pixels.length; i += 4) {
      if (!(mask.pixels[i] > 0.5)) continue;
      compared++;
      const expected = [colour.r, colour.g, colour.b].map((c, k) => clear.pixels[i + k] * (1 - f) + c * f);
      for (let k = 0; k < 3; k++) {
        worst = Math.max(worst, Math.abs(on.pixels[i + k] - expected[k]));
        level = Math.max(level, expected[k]);
      }
    }
    return { worst, level, compared, factor: f };
  } finally {
    renderer.dispose();
    renderer.forceContextLoss();
  }
}

/**
 * A pixel ratio of 2 at 48 × 32 CSS pixels: the frame of a pixel ratio of 1 at 96 × 64 (the
 * pipeline sizes itself from the composer's device pixels).
 */
async function pixelRatioRow() {
  const run = async (ratio) => {
    const renderer = new THREE.WebGLRenderer({ antialias: false });
    renderer.setPixelRatio(ratio);
    renderer.setSize(WIDTH / ratio, HEIGHT / ratio, false);
    const built = baseScene((scene) => { slab(scene, skin()); });
    const composer = createComposer(renderer);
    composer.setPixelRatio(ratio);
    composer.setSize(WIDTH / ratio, HEIGHT / ratio);
    const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: 1000, lightDepthSize: 256 });
    for (const material of skinMaterials(built.scene)) sss.makeSubsurface(material, { widthMm: WIDTH_MM });
    composer.addPass(sss);
    composer.render();
    composer.render();
    const pixels = await read(renderer, composer.readBuffer);
    const size = [composer.readBuffer.width, composer.readBuffer.height];
    sss.dispose();
    composer.dispose();
    renderer.dispose();
    renderer.forceContextLoss();
    return { pixels, size };
  };
  const one = await run(1);
  const two = await run(2);
  return { ...compare(two.pixels, one.pixels), sizes: [one.size, two.size] };
}

/**
 * A second camera in the frame (a minimap rendered between the composer's frames with three's
 * renderer.render): the pipeline's frame is unchanged, and the minimap is three's own picture of
 * the subsurface material (no transmittance, nothing split).
 */
async function secondCameraRow() {
  const renderer = createRenderer();
  try {
    const built = baseScene((scene) => { slab(scene, skin()); });
    const minimapCamera = new THREE.PerspectiveCamera(40, WIDTH / HEIGHT, 0.05, 20);
    minimapCamera.position.set(0.6, 0.4, 0.8);
    minimapCamera.lookAt(0, 0, 0);
    const minimap = new THREE.WebGLRenderTarget(WIDTH, HEIGHT, { type: THREE.HalfFloatType });
    const drawMinimap = () => {
      renderer.setRenderTarget(minimap);
      renderer.render(built.scene, minimapCamera);
      renderer.setRenderTarget(null);
    };
    const alone = await frame(renderer, built, 'on');
    const between = await frame(renderer, built, 'on', { before: drawMinimap });
    const minimapDuring = await read(renderer, minimap);
    drawMinimap(); // after the pipeline's dispose: three's own material
    const minimapPlain = await read(renderer, minimap);
    minimap.dispose();
    return { frame: compare(between.pixels, alone.pixels), minimap: compare(minimapDuring, minimapPlain), glError: renderer.getContext().getError() };
  } finally {
    renderer.dispose();
    renderer.forceContextLoss();
  }
}

window.sceneGraph = { rows: Object.keys(ROWS), row, fogRow, pixelRatioRow, secondCameraRow, size: { width: WIDTH, height: HEIGHT } };
window.testReady = true;
