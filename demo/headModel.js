// Loads the Lee Perry-Smith scan with its three maps, or, when the asset step could not provide it
// (public/assets/head-status.json says so, or a load fails), the procedural stand-in bust.
import { Mesh, MeshPhysicalMaterial, SRGBColorSpace, TextureLoader, Vector2 } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { createStandInBust, createStandInTextures } from './standInBust.js';

const HEAD_DIR = 'assets/LeePerrySmith/';
export const HEAD_FILES = [
  'LeePerrySmith.glb',
  'Map-COL.jpg',
  'Map-SPEC.jpg',
  'Infinite-Level_02_Tangent_SmoothUV.jpg',
];

/** Skin material shared by the scan and the stand-in; specular from the SPEC map's tint. */
function createSkinMaterial({ map, specularMap, normalMap }) {
  return new MeshPhysicalMaterial({
    map,
    normalMap,
    normalScale: new Vector2(0.8, 0.8),
    // Map-SPEC.jpg is a grey specular-intensity map: three reads specularColorMap's RGB.
    specularColorMap: specularMap,
    specularIntensity: 1,
    roughness: 0.45,
    metalness: 0,
  });
}

async function headStatus(base) {
  try {
    const response = await fetch(`${base}assets/head-status.json`, { cache: 'no-store' });
    if (!response.ok) return null;
    return await response.json();
  } catch {
    return null;
  }
}

/**
 * @param {{ base?: string, forceStandIn?: boolean, onProgress?: (fraction: number) => void }} [options]
 * @returns {Promise<{ mesh: Mesh, isStandIn: boolean, missing: string[], reason?: string }>}
 */
export async function loadHead({ base = './', forceStandIn = false, onProgress = () => {} } = {}) {
  if (forceStandIn) return standIn(HEAD_FILES, 'the page was asked for the stand-in (?standIn)');
  const status = await headStatus(base);
  if (status && status.complete) {
    try {
      let done = 0;
      const step = () => onProgress(++done / 4);
      const textureLoader = new TextureLoader();
      const loadTexture = (file) => textureLoader.loadAsync(base + HEAD_DIR + file).then((t) => (step(), t));
      const [gltf, map, specularMap, normalMap] = await Promise.all([
        new GLTFLoader().loadAsync(base + HEAD_DIR + HEAD_FILES[0]).then((g) => (step(), g)),
        loadTexture(HEAD_FILES[1]),
        loadTexture(HEAD_FILES[2]),
        loadTexture(HEAD_FILES[3]),
      ]);
      map.colorSpace = SRGBColorSpace;
      specularMap.colorSpace = SRGBColorSpace;
      let source = null;
      gltf.scene.traverse((o) => { if (!source && o.isMesh) source = o; });
      const mesh = new Mesh(source.geometry, createSkinMaterial({ map, specularMap, normalMap }));
      mesh.name = 'LeePerrySmith';
      return { mesh, isStandIn: false, missing: [] };
    } catch (error) {
      return standIn(HEAD_FILES, `loading the scan failed: ${error.message}`);
    }
  }
  const missing = status?.missing?.length ? status.missing : HEAD_FILES;
  return standIn(missing, status ? 'the asset step did not find them' : 'public/assets/head-status.json is missing (run npm run assets)');
}

function standIn(missing, reason) {
  const mesh = new Mesh(createStandInBust(), createSkinMaterial(createStandInTextures()));
  mesh.name = 'StandInBust';
  return { mesh, isStandIn: true, missing, reason };
}
