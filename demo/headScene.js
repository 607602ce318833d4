// The demo's scene: the head, a shadow-casting spot light, soft ambient light, a camera framing the
// face, and a point light behind the right ear (hidden: the demo's `pointLight` shows it). Shared by the page, the figure renderer and the bench so they all show the same thing.
import {
  Color, HemisphereLight, IcosahedronGeometry, Mesh, MeshStandardMaterial, PerspectiveCamera, PointLight, Scene, SpotLight, Vector3,
} from 'three';

/** The scan is about 5 cm per world unit (REFERENCE §9): 8.55 units ≈ 43 cm across the shoulders. */
export const HEAD_WORLD_UNIT_IN_MM = 50;

/** A point on the face (right cheek beside the nose), in the scan's coordinates (Y up, facing +Z). */
export const FACE_CENTRE = new Vector3(0.6, 1.0, 2.1);

/** Camera position and orbit target (x, y, z, tx, ty, tz): head and shoulders, facing us. */
export const DEFAULT_CAMERA = Object.freeze([0, 1.0, 21, 0, 0.9, 0]);

/** The middle of the head: what the camera orbits and the light aims at. */
export const HEAD_CENTRE = new Vector3(0, 1.3, 0.4);

export function createHeadScene(headMesh) {
  const scene = new Scene();
  scene.background = new Color(0x101014);

  headMesh.castShadow = true;
  headMesh.receiveShadow = true;
  scene.add(headMesh);

  scene.add(new HemisphereLight(0xcfd8ff, 0x2a1f1a, 0.5));

  // decay 0: irradiance = intensity · cos θ, so π gives a white Lambert surface radiance ≈ 1.
  const light = new SpotLight(0xffffff, 2.6, 0, Math.PI / 7, 0.35, 0);
  light.castShadow = true;
  light.shadow.mapSize.set(1024, 1024);
  light.shadow.camera.near = 5;
  light.shadow.camera.far = 40;
  // Against shadow acne on the skin at grazing light: a small depth bias plus a normal offset of
  // 0.02 units (1 mm), below the thickness of the ears so they still shadow the head.
  light.shadow.bias = -0.0005;
  light.shadow.normalBias = 0.02;
  light.target.position.copy(HEAD_CENTRE);
  scene.add(light, light.target);

  const camera = new PerspectiveCamera(25, 16 / 9, 1, 100);
  camera.position.fromArray(DEFAULT_CAMERA, 0);
  camera.lookAt(DEFAULT_CAMERA[3], DEFAULT_CAMERA[4], DEFAULT_CAMERA[5]);

  const pointLight = createEarLight();
  scene.add(pointLight);

  const rig = { scene, camera, light, pointLight, head: headMesh, facePoint: FACE_CENTRE };
  setLightDirection(rig, 30, 25);
  return rig;
}

/** The bowl of the right ear (its concha), on the surface seen from figure 2's camera. */
export const RIGHT_EAR = new Vector3(1.65, 1.5, -0.13);

/**
 * A second light for transmittance: a point light 6 cm behind the right ear, so the ear glows
 * while the key light stays. No shadow map of three's (the pipeline draws its own thickness map);
 * decay 2 and a short range keep its light on the ear and the nape.
 * @returns {PointLight} hidden until shown
 */
export function createEarLight() {
  const light = new PointLight(0xffe2c4, 8, 6, 2);
  light.name = 'ear light';
  light.position.set(1.9, 1.6, -1.4);
  light.visible = false;
  return light;
}

/**
 * A marble ball beside the head, left of it in the full-head shot (6 cm across, 0.6 units of ~5 cm),
 * hidden: the demo shows it with its own profile ('marble') in the head's pipeline (its `marble` key).
 * @returns {Mesh}
 */
export function createMarblePiece() {
  // Detail 5: a smooth silhouette at the head shot's scale.
  const piece = new Mesh(new IcosahedronGeometry(0.6, 5), new MeshStandardMaterial({ color: 0xf2efe8, roughness: 0.25 }));
  piece.name = 'marble piece';
  piece.position.set(-2.7, 1.2, 1.0);
  piece.castShadow = piece.receiveShadow = true;
  piece.visible = false;
  return piece;
}

/**
 * Places the light on a sphere around the head.
 * @param {number} azimuthDeg around the vertical axis; 0 = camera side (+Z), 180 = behind the head
 * @param {number} elevationDeg above the horizontal plane
 * @param {number} [distance=18] world units from the face centre
 */
export function setLightDirection({ light }, azimuthDeg, elevationDeg, distance = 18) {
  const az = (azimuthDeg * Math.PI) / 180;
  const el = (elevationDeg * Math.PI) / 180;
  light.position.set(
    HEAD_CENTRE.x + distance * Math.cos(el) * Math.sin(az),
    HEAD_CENTRE.y + distance * Math.sin(el),
    HEAD_CENTRE.z + distance * Math.cos(el) * Math.cos(az),
  );
  light.target.position.copy(HEAD_CENTRE);
  light.updateMatrixWorld();
  light.target.updateMatrixWorld();
}
