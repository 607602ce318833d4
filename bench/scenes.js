// The bench's scenes (browser side): the demo's head (1, 4 or 16 of them at equal screen
// coverage) and three synthetic ones that isolate what screen-space scattering gets wrong: a hard
// light edge in every direction, a depth edge, a plane seen at a grazing angle.
// Each builder returns { scene, camera, light, subsurface: [materials], worldUnitInMm, widthMm }:
// `light` (or null) drives transmittance; every subsurface material gets `widthMm`.
import {
  AmbientLight, Box3, Color, DataTexture, DirectionalLight, FloatType, LinearFilter, Mesh,
  MeshStandardMaterial, PerspectiveCamera, PlaneGeometry, RGBAFormat, RepeatWrapping, Scene, SpotLight, Vector3,
} from 'three';
import { loadHead } from '../demo/headModel.js';
import { createHeadScene, FACE_CENTRE, HEAD_WORLD_UNIT_IN_MM } from '../demo/headScene.js';

/** The synthetic scenes' scale: 1 unit = 5 cm, so at 640×360 one profile mm spans about 2 pixels. */
const SYNTHETIC_UNIT_IN_MM = 50;

function camera(aspect, fovY = 20, distance = 10) {
  const c = new PerspectiveCamera(fovY, aspect, 0.5, 100);
  c.position.set(0, 0, distance);
  c.lookAt(0, 0, 0);
  c.updateMatrixWorld();
  return c;
}

function skinMaterial(colour = 0xffffff, map = null) {
  return new MeshStandardMaterial({ color: colour, roughness: 1, metalness: 0, map });
}

/** Smooth value noise in [0.25, 1] (sum of sines: deterministic, no texture seams at repeat 1). */
function noiseTexture(size = 256) {
  const data = new Float32Array(size * size * 4);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const u = (x / size) * 2 * Math.PI;
      const v = (y / size) * 2 * Math.PI;
      const n = 0.5 + 0.2 * Math.sin(7 * u + 3 * v) + 0.15 * Math.sin(19 * u - 11 * v) + 0.1 * Math.sin(41 * v + 5 * u);
      const value = 0.25 + 0.75 * Math.min(Math.max(n, 0), 1);
      data.set([value, value * 0.85, value * 0.7, 1], (y * size + x) * 4);
    }
  }
  const texture = new DataTexture(data, size, size, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = LinearFilter;
  texture.wrapS = texture.wrapT = RepeatWrapping;
  texture.needsUpdate = true;
  return texture;
}

const SYNTHETIC = {
  /** A white slab facing the camera; a hard-edged spot light draws a disc: an edge in every direction. */
  slab({ aspect }) {
    const scene = new Scene();
    const material = skinMaterial();
    scene.add(new Mesh(new PlaneGeometry(20, 20), material));
    const spot = new SpotLight(0xffffff, 3, 0, Math.atan(1 / 10), 0, 0); // penumbra 0: a hard edge
    spot.position.set(0, 0, 10);
    scene.add(spot, spot.target, new AmbientLight(0xffffff, 0.15));
    return { scene, camera: camera(aspect), light: null, subsurface: [material] };
  },
  /** A bright textured slab over the left half, 3 cm in front of a dim one: nothing may cross the step. */
  depthEdge({ aspect }) {
    const scene = new Scene();
    const far = skinMaterial(0x333333);
    const near = skinMaterial(0xffffff, noiseTexture());
    near.map.repeat.set(2, 4);
    scene.add(new Mesh(new PlaneGeometry(20, 20), far));
    const front = new Mesh(new PlaneGeometry(10, 20), near);
    front.position.set(-5, 0, 30 / SYNTHETIC_UNIT_IN_MM);
    scene.add(front);
    const light = new DirectionalLight(0xffffff, Math.PI);
    light.position.set(0, 0, 10);
    scene.add(light, light.target);
    return { scene, camera: camera(aspect), light: null, subsurface: [far, near] };
  },
  /** A textured plane tilted 75° away from the camera: depth changes fast along the screen's y. */
  grazing({ aspect, tiltDeg = 75 }) {
    const scene = new Scene();
    const material = skinMaterial(0xffffff, noiseTexture());
    material.map.repeat.set(6, 6);
    const plane = new Mesh(new PlaneGeometry(40, 40), material);
    plane.rotation.x = -(tiltDeg * Math.PI) / 180;
    plane.position.y = -1.5;
    scene.add(plane);
    const light = new DirectionalLight(0xffffff, 4);
    light.position.set(0, 10, 4);
    scene.add(light, light.target, new AmbientLight(0xffffff, 0.2));
    return { scene, camera: camera(aspect), light: null, subsurface: [material] };
  },
};

let headPromise = null;

/** The demo's head mesh, loaded once per page (the scan, or the stand-in when it is missing). */
function head() {
  headPromise ??= loadHead({ base: '/' });
  return headPromise;
}

/**
 * The demo's head scene with `count` heads (1, 4, 16) in a √count × √count grid, each scaled by
 * 1/√count: they cover about the same pixels as one head. The width per world unit is kept, so the
 * kernel spans the same pixels: only the number of objects changes.
 */
async function heads({ aspect, count = 1 }) {
  const loaded = await head();
  // A fresh mesh and material per scene: the pipeline hooks the material it is given.
  const mesh = loaded.mesh.clone();
  mesh.material = loaded.mesh.material.clone();
  const rig = createHeadScene(mesh);
  rig.camera.aspect = aspect;
  rig.camera.updateProjectionMatrix();
  rig.camera.lookAt(FACE_CENTRE);
  rig.camera.updateMatrixWorld();
  const k = Math.round(Math.sqrt(count));
  if (k * k !== count) throw new RangeError(`heads: count must be a square, got ${count}`);
  if (k > 1) {
    const bounds = new Box3().setFromObject(rig.head);
    const centre = bounds.getCenter(new Vector3());
    const size = bounds.getSize(new Vector3());
    rig.scene.remove(rig.head);
    for (let i = 0; i < k; i++) {
      for (let j = 0; j < k; j++) {
        const copy = rig.head.clone();
        copy.scale.setScalar(1 / k);
        const offset = new Vector3(((i - (k - 1) / 2) * size.x) / k, ((j - (k - 1) / 2) * size.y) / k, 0);
        copy.position.copy(centre).add(offset).addScaledVector(centre, -1 / k);
        rig.scene.add(copy);
      }
    }
  }
  return {
    scene: rig.scene, camera: rig.camera, light: rig.light, subsurface: [rig.head.material],
    worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, widthMm: 1, isStandIn: loaded.isStandIn,
    rig: count === 1 ? rig : null, // what bench/babylonHead.js copies (one head only)
  };
}

export const SCENE_NAMES = ['head', 'heads4', 'heads16', ...Object.keys(SYNTHETIC)];

/**
 * @param {string} name one of SCENE_NAMES
 * @param {{ aspect: number }} options
 */
export async function buildScene(name, { aspect, tiltDeg }) {
  if (name === 'head') return heads({ aspect, count: 1 });
  if (name === 'heads4') return heads({ aspect, count: 4 });
  if (name === 'heads16') return heads({ aspect, count: 16 });
  const build = SYNTHETIC[name];
  if (!build) throw new RangeError(`buildScene: unknown scene ${name}; known: ${SCENE_NAMES.join(', ')}`);
  const built = build({ aspect, tiltDeg });
  built.scene.background = new Color(0x000000);
  return { ...built, worldUnitInMm: SYNTHETIC_UNIT_IN_MM, widthMm: 1, isStandIn: false };
}
