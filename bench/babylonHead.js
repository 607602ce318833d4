// The peer of the bench (browser side): Babylon.js drawing the head of bench/scenes.js from the
// same scan file (public/assets/LeePerrySmith/LeePerrySmith.glb, through @babylonjs/loaders), with
// the same maps, camera, lights and resolution, read from the three.js rig (demo/headScene.js) so
// the two cannot drift apart. Two scenes on one engine: plain, and with Babylon's own screen-space
// subsurface scattering (its prepass renderer: scene.enableSubSurfaceForPrePass(), the material's
// subSurface.isScatteringEnabled), so switching between them recompiles nothing.
//
// What is matched, and how:
// - geometry: the scan's mesh alone (three's loader keeps only its geometry too), right-handed
//   coordinates (scene.useRightHandedSystem) so positions are three's;
// - camera: position, target, vertical field of view, near and far;
// - spot light: position, direction, cone (Babylon's `angle` is the full cone: twice three's), no
//   distance falloff (three's decay 0: FALLOFF_STANDARD with an unbounded range), 1024² PCF shadow
//   map; the hemisphere light: sky and ground colours along +Y;
// - material: PBR metallic-roughness with the three.js material's colour, metalness, roughness and
//   normal scale, its colour map (sRGB), normal map, and specular map as reflectance;
// - SSS: Babylon's Burley profile with the scatter distances of our skinBurley preset (the same
//   99.7 % radius per channel as d'Eon skin), at the scan's 50 mm per unit.
// - image: ACES tone mapping at three's exposure, sRGB (what OutputPass does after the three.js
//   frames), for the screenshots; the timed frames include it in both engines alike.
// The plain frames agree: bench/peers.js compares them every run (silhouette overlap, mean luma).
import { Engine } from '@babylonjs/core/Engines/engine.js';
import { Scene } from '@babylonjs/core/scene.js';
import { FreeCamera } from '@babylonjs/core/Cameras/freeCamera.js';
import { SpotLight } from '@babylonjs/core/Lights/spotLight.js';
import { HemisphericLight } from '@babylonjs/core/Lights/hemisphericLight.js';
import { Light } from '@babylonjs/core/Lights/light.js';
import { ShadowGenerator } from '@babylonjs/core/Lights/Shadows/shadowGenerator.js';
import '@babylonjs/core/Lights/Shadows/shadowGeneratorSceneComponent.js';
import { PBRMaterial } from '@babylonjs/core/Materials/PBR/pbrMaterial.js';
import { Texture } from '@babylonjs/core/Materials/Textures/texture.js';
import { Color3, Color4 } from '@babylonjs/core/Maths/math.color.js';
import { Vector3 } from '@babylonjs/core/Maths/math.vector.js';
import { ImageProcessingConfiguration } from '@babylonjs/core/Materials/imageProcessingConfiguration.js';
import { LoadAssetContainerAsync } from '@babylonjs/core/Loading/sceneLoader.js';
import '@babylonjs/core/Rendering/prePassRendererSceneComponent.js';
import '@babylonjs/core/Rendering/subSurfaceSceneComponent.js';
import '@babylonjs/loaders/glTF/2.0/index.js';
import '@babylonjs/loaders/glTF/glTFFileLoader.js';
import { Vector3 as ThreeVector3 } from 'three';
import { SKIN_BURLEY_SCATTER_DISTANCE_MM } from '/src/profiles/presets.js';
import { HEAD_FILES } from '../demo/headModel.js';

/** Where the asset step puts the scan (demo/headModel.js loads it from there too). */
const HEAD_DIR = '/assets/LeePerrySmith/';

/** three's ACESFilmicToneMapping scales the colour by exposure / 0.6 before the curve; Babylon's does not. */
const THREE_ACES_EXPOSURE = 1 / 0.6;
/**
 * Babylon's HemisphericLight lights a PBR material π times as brightly as three's HemisphereLight
 * of the same intensity (measured on this head, each light alone: the spot needs no factor).
 */
const HEMISPHERE_SCALE = 1 / Math.PI;

const toVector = (v) => new Vector3(v.x, v.y, v.z);
const toColor = (c) => new Color3(c.r, c.g, c.b);

/**
 * One Babylon scene of the head as `rig` (demo/headScene.js's createHeadScene) sets it up.
 * @param {Engine} engine
 * @param {object} rig { scene, camera, light } of three.js
 * @param {{ subsurface: boolean, worldUnitInMm: number }} options
 */
async function headScene(engine, rig, { subsurface, worldUnitInMm }) {
  const scene = new Scene(engine);
  scene.useRightHandedSystem = true;
  const background = rig.scene.background;
  scene.clearColor = new Color4(background.r, background.g, background.b, 1);
  scene.imageProcessingConfiguration.toneMappingEnabled = true;
  scene.imageProcessingConfiguration.toneMappingType = ImageProcessingConfiguration.TONEMAPPING_ACES;
  scene.imageProcessingConfiguration.exposure = THREE_ACES_EXPOSURE;

  const container = await LoadAssetContainerAsync(`${HEAD_DIR}${HEAD_FILES[0]}`, scene);
  container.addAllToScene();
  const mesh = container.meshes.find((m) => m.name === 'LeePerrySmith');
  if (!mesh) throw new Error('babylonHead: no mesh named LeePerrySmith in the scan');

  const three = rig.camera;
  const camera = new FreeCamera('camera', toVector(three.position), scene);
  camera.setTarget(toVector(three.position).add(toVector(three.getWorldDirection(new ThreeVector3()))));
  camera.fov = (three.fov * Math.PI) / 180;
  camera.minZ = three.near;
  camera.maxZ = three.far;
  scene.activeCamera = camera;

  const spot = rig.light;
  const spotDirection = toVector(spot.target.position).subtract(toVector(spot.position)).normalize();
  const light = new SpotLight('spot', toVector(spot.position), spotDirection, 2 * spot.angle, 0, scene);
  light.falloffType = Light.FALLOFF_STANDARD;
  light.range = Number.MAX_VALUE;
  light.innerAngle = 2 * spot.angle * (1 - spot.penumbra);
  light.intensity = spot.intensity;
  light.diffuse = toColor(spot.color);
  light.specular = toColor(spot.color);
  let hemisphere = null;
  rig.scene.traverse((o) => { if (o.isHemisphereLight) hemisphere = o; });
  if (hemisphere) {
    const sky = new HemisphericLight('hemisphere', new Vector3(0, 1, 0), scene);
    sky.diffuse = toColor(hemisphere.color);
    sky.groundColor = toColor(hemisphere.groundColor);
    sky.specular = new Color3(0, 0, 0);
    sky.intensity = hemisphere.intensity * HEMISPHERE_SCALE;
  }
  light.shadowMinZ = spot.shadow.camera.near;
  light.shadowMaxZ = spot.shadow.camera.far;
  const shadows = new ShadowGenerator(spot.shadow.mapSize.x, light);
  shadows.usePercentageCloserFiltering = true;
  shadows.bias = Math.abs(spot.shadow.bias);
  shadows.normalBias = spot.shadow.normalBias;
  shadows.addShadowCaster(mesh);
  mesh.receiveShadows = true;

  // The maps of demo/headModel.js, invertY as three's TextureLoader (flipY) reads them.
  const [, colourMap, specularMap, normalMap] = HEAD_FILES;
  const texture = (file, srgb) => new Texture(`${HEAD_DIR}${file}`, scene, { invertY: true, gammaSpace: srgb });
  const skin = rig.head.material;
  const material = new PBRMaterial('skin', scene);
  material.albedoTexture = texture(colourMap, true);
  material.albedoColor = toColor(skin.color);
  material.bumpTexture = texture(normalMap, false);
  material.bumpTexture.level = skin.normalScale.x;
  material.reflectanceTexture = texture(specularMap, true);
  material.metallic = skin.metalness;
  material.roughness = skin.roughness;
  if (subsurface) {
    const config = scene.enableSubSurfaceForPrePass();
    config.metersPerUnit = worldUnitInMm / 1000;
    config.clearAllDiffusionProfiles();
    const profile = new Color3(...SKIN_BURLEY_SCATTER_DISTANCE_MM);
    config.addDiffusionProfile(profile);
    material.subSurface.isScatteringEnabled = true;
    material.subSurface.scatteringDiffusionProfile = profile;
  }
  mesh.material = material;
  await scene.whenReadyAsync();
  return { scene, mesh, camera };
}

/**
 * Renders `scene` until its image stops changing: Babylon skips a post-process (the SSS, the
 * prepass composition) while its shader is still compiling, which on SwiftShader (parallel shader
 * compilation) lasts a few frames after whenReadyAsync; until then its SSS frame is the plain one.
 */
async function settled(scene, gl, width, height, { maxFrames = 60 } = {}) {
  const read = () => {
    const pixels = new Uint8Array(width * height * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return pixels;
  };
  const same = (a, b) => a.every((v, i) => v === b[i]);
  scene.render();
  let last = read();
  for (let frame = 1; frame < maxFrames; frame++) {
    await new Promise((resolve) => setTimeout(resolve, 20));
    scene.render();
    const image = read();
    if (same(image, last)) return;
    last = image;
  }
  throw new Error(`babylonHead: the image still changes after ${maxFrames} frames`);
}

/**
 * A Babylon engine on its own canvas of width × height with the plain and the SSS scene.
 * @param {object} rig three's head rig
 * @param {{ width: number, height: number, worldUnitInMm: number }} options
 */
export async function createBabylonHead(rig, { width, height, worldUnitInMm }) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const engine = new Engine(canvas, false, { preserveDrawingBuffer: true, stencil: true, antialias: false }, false);
  engine.setSize(width, height);
  const plain = await headScene(engine, rig, { subsurface: false, worldUnitInMm });
  const sss = await headScene(engine, rig, { subsurface: true, worldUnitInMm });
  const gl = engine._gl;
  for (const { scene } of [plain, sss]) await settled(scene, gl, width, height);
  return {
    engine, canvas, plain, sss,
    gl,
    dispose() {
      plain.scene.dispose();
      sss.scene.dispose();
      engine.dispose();
    },
  };
}
