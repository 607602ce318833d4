// Procedural stand-in for the Lee Perry-Smith head scan, used when the scan is not available
// (public/assets/head-status.json says incomplete). Same frame as LeePerrySmith.glb: Y up, facing
// +Z, 1 unit ~ 5 cm, bounding box about 8.55 x 7.95 x 5.18 centred on the origin (the glb's POSITION
// accessor: min (-4.276, -3.973, -2.590), max (4.276, 3.973, 2.590); nose tip near (0, 1.10, 2.59);
// ears at |x| 1.6-1.9, y 0.85-1.87, z -0.23..0.24; skull |x| <~ 1.4; shoulders |x| up to 4.28).
//
// Built from closed, deformed spheres merged into one indexed geometry (overlaps are hidden by the
// depth test): a skull-and-face head with nose, brow, eye sockets, lips and chin; two THIN ears
// (0.08 units ~ 4 mm thick, so back-lit transmittance shows through them); a neck; shoulders.
// Normals come from finite differences of each part's analytic map (smooth, no seams), tangents
// from the map's derivative along +u (three.js's convention: w = handedness against +v).
// Deterministic: no Math.random; the textures use a seeded PRNG (seededRandom.js).

import {
  BufferGeometry,
  DataTexture,
  Float32BufferAttribute,
  LinearFilter,
  LinearMipmapLinearFilter,
  NoColorSpace,
  RGBAFormat,
  RepeatWrapping,
  SRGBColorSpace,
  Uint32BufferAttribute,
  UnsignedByteType,
} from 'three';
import { mulberry32 } from './seededRandom.js';

// ---------------------------------------------------------------------------------------------
// Layout (world units; 1 unit ~ 5 cm). Exported so tests and the demo can aim at the parts.

const EAR_ANGLE = (35 * Math.PI) / 180; // ear plane turned out from the head's side (back edge flares)

export const STAND_IN_LAYOUT = Object.freeze({
  bbox: Object.freeze({ min: [-4.276, -3.973, -2.59], max: [4.276, 3.973, 2.59] }),
  head: Object.freeze({ center: [0, 1.47, 0.15], radii: [1.38, 2.5, 2.05] }),
  noseTip: Object.freeze([0, 1.1, 2.59]),
  ear: Object.freeze({
    // right ear (x > 0); the left one is its mirror image
    center: [1.25 + 0.4 * Math.sin(EAR_ANGLE), 1.36, 0.35 - 0.4 * Math.cos(EAR_ANGLE)],
    halfWidth: 0.4, // along uW (front edge buried in the head, back edge free)
    halfHeight: 0.52, // along Y
    halfThickness: 0.04, // along uN: 0.08 units ~ 4 mm
    cup: 0.03, // bowl depth of the ear shell (keeps the thickness)
    uW: [Math.sin(EAR_ANGLE), 0, -Math.cos(EAR_ANGLE)],
    uN: [Math.cos(EAR_ANGLE), 0, Math.sin(EAR_ANGLE)],
  }),
  neck: Object.freeze({ center: [0, -1.0, -0.35], radii: [1.25, 2.1, 1.35] }),
  torso: Object.freeze({ center: [0, -3.1, -0.77], radii: [4.276, 1.25, 1.82], bottomY: -3.973 }),
});

// ---------------------------------------------------------------------------------------------
// small helpers

const clamp01 = (x) => (x < 0 ? 0 : x > 1 ? 1 : x);
function smoothstep(e0, e1, x) {
  const t = clamp01((x - e0) / (e1 - e0));
  return t * t * (3 - 2 * t);
}
const gauss2 = (dx, sx, dy, sy) => Math.exp(-(dx * dx) / (sx * sx) - (dy * dy) / (sy * sy));
const spow = (x, p) => Math.sign(x) * Math.abs(x) ** p;

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
function normalize(a) {
  const l = Math.hypot(a[0], a[1], a[2]) || 1;
  return [a[0] / l, a[1] / l, a[2] / l];
}

// Unit direction for grid angles, with three's SphereGeometry convention (outward winding below).
function dirAt(phi, theta) {
  const s = Math.sin(theta);
  return [-Math.cos(phi) * s, Math.cos(theta), Math.sin(phi) * s];
}

/**
 * Tessellate a closed surface given as a map from unit directions to positions (orientation
 * preserving, i.e. star-like around the part). Lat-long grid, poles on +-Y.
 * Returns plain arrays: { positions, normals, uvs, tangents, indices }.
 */
function tessellate(map, widthSegments, heightSegments) {
  const positions = [];
  const normals = [];
  const uvs = [];
  const tangents = [];
  const indices = [];
  const eps = 1e-4;
  const grid = [];
  let index = 0;

  for (let iy = 0; iy <= heightSegments; iy++) {
    const row = [];
    const v = iy / heightSegments;
    const theta = v * Math.PI;
    // the derivative along u vanishes at the poles: take it just off the pole
    const thetaT = Math.min(Math.max(theta, 1e-3), Math.PI - 1e-3);
    for (let ix = 0; ix <= widthSegments; ix++) {
      const u = ix / widthSegments;
      const phi = u * 2 * Math.PI;
      const d = dirAt(phi, theta);
      const p = map(d);

      // normal: cross product of the map's differentials along two tangents of the unit sphere
      const a = Math.abs(d[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
      const t1 = normalize(cross(a, d));
      const t2 = cross(d, t1); // t1 x t2 = d
      const along = (t) =>
        sub(map(normalize([d[0] + eps * t[0], d[1] + eps * t[1], d[2] + eps * t[2]])),
          map(normalize([d[0] - eps * t[0], d[1] - eps * t[1], d[2] - eps * t[2]])));
      const n = normalize(cross(along(t1), along(t2)));

      // tangent along +u, bitangent sign against +v (uv.y = 1 - v)
      const dpdu = sub(map(dirAt(phi + 1e-4, thetaT)), map(dirAt(phi - 1e-4, thetaT)));
      const dpdv = sub(map(dirAt(phi, thetaT - 1e-4)), map(dirAt(phi, thetaT + 1e-4))); // +uv.y = -theta
      const tg = normalize(sub(dpdu, n.map((c) => c * dot(n, dpdu))));
      const w = dot(cross(n, tg), dpdv) < 0 ? -1 : 1;

      positions.push(p[0], p[1], p[2]);
      normals.push(n[0], n[1], n[2]);
      uvs.push(u, 1 - v);
      tangents.push(tg[0], tg[1], tg[2], w);
      row.push(index++);
    }
    grid.push(row);
  }

  for (let iy = 0; iy < heightSegments; iy++) {
    for (let ix = 0; ix < widthSegments; ix++) {
      const a = grid[iy][ix + 1];
      const b = grid[iy][ix];
      const c = grid[iy + 1][ix];
      const d = grid[iy + 1][ix + 1];
      if (iy !== 0) indices.push(a, b, d);
      if (iy !== heightSegments - 1) indices.push(b, c, d);
    }
  }
  return { positions, normals, uvs, tangents, indices };
}

/** Mirror a tessellated part through x = 0 (winding flipped, tangent handedness flipped). */
function mirrorX(part) {
  const positions = part.positions.slice();
  const normals = part.normals.slice();
  const tangents = part.tangents.slice();
  for (let i = 0; i < positions.length; i += 3) {
    positions[i] = -positions[i];
    normals[i] = -normals[i];
  }
  for (let i = 0; i < tangents.length; i += 4) {
    tangents[i] = -tangents[i];
    tangents[i + 3] = -tangents[i + 3];
  }
  const indices = part.indices.slice();
  for (let i = 0; i < indices.length; i += 3) {
    const t = indices[i + 1];
    indices[i + 1] = indices[i + 2];
    indices[i + 2] = t;
  }
  return { positions, normals, uvs: part.uvs.slice(), tangents, indices };
}

function toGeometry(parts, name) {
  const positions = [];
  const normals = [];
  const uvs = [];
  const tangents = [];
  const indices = [];
  for (const part of parts) {
    const base = positions.length / 3;
    for (const x of part.positions) positions.push(x);
    for (const x of part.normals) normals.push(x);
    for (const x of part.uvs) uvs.push(x);
    for (const x of part.tangents) tangents.push(x);
    for (const i of part.indices) indices.push(base + i);
  }
  const g = new BufferGeometry();
  g.name = name;
  g.setIndex(new Uint32BufferAttribute(indices, 1));
  g.setAttribute('position', new Float32BufferAttribute(positions, 3));
  g.setAttribute('normal', new Float32BufferAttribute(normals, 3));
  g.setAttribute('uv', new Float32BufferAttribute(uvs, 2));
  g.setAttribute('tangent', new Float32BufferAttribute(tangents, 4));
  g.computeBoundingBox();
  g.computeBoundingSphere();
  return g;
}

// ---------------------------------------------------------------------------------------------
// the parts, each a map from a unit direction to a position

const NOSE = 0.4;

function headMap(d) {
  const { center: C, radii: R } = STAND_IN_LAYOUT.head;
  // a slightly boxy ellipsoid (superquadric, exponent 2.4): fuller cranium than an ellipsoid
  const q = 2.4;
  const s = (Math.abs(d[0] / R[0]) ** q + Math.abs(d[1] / R[1]) ** q + Math.abs(d[2] / R[2]) ** q) ** (-1 / q);
  let x = s * d[0];
  const y = s * d[1];
  let z = s * d[2];
  const Y = C[1] + y; // world height

  const front = smoothstep(-0.05, 0.55, d[2]); // only the face side gets the face features
  // jaw: the lower head narrows, the lower face comes forward (mouth and chin)
  x *= 1 - 0.32 * smoothstep(-0.6, -2.3, y);
  z += front * 0.45 * smoothstep(-0.45, -1.85, y) * Math.exp(-((x / 1.15) ** 2)) * (1 - smoothstep(-2.2, -2.5, y));
  // brow ridge, eye sockets, cheekbones, lips, chin
  z += front * 0.1 * gauss2(x, 1.0, Y - 2.2, 0.18);
  z -= front * 0.2 * (gauss2(x - 0.52, 0.3, Y - 1.78, 0.22) + gauss2(x + 0.52, 0.3, Y - 1.78, 0.22));
  x += Math.sign(x) * front * 0.08 * gauss2(Math.abs(x) - 1.1, 0.35, Y - 1.3, 0.3);
  z += front * 0.1 * gauss2(x, 0.45, Y - 0.28, 0.14);
  z += front * 0.08 * gauss2(x, 0.5, Y + 0.72, 0.22);
  // nose: a ridge from the brow (y ~ 2.0) to the tip (y ~ 1.1), falling off sharply below the tip
  const tipY = STAND_IN_LAYOUT.noseTip[1];
  const along = smoothstep(2.1, tipY, Y) ** 1.4 * (1 - smoothstep(tipY, tipY - 0.28, Y) ** 0.8);
  const halfWidth = 0.1 + 0.2 * smoothstep(2.0, tipY, Y); // narrow bridge, wide nostrils
  z += front * NOSE * along * Math.exp(-((x / halfWidth) ** 2));
  return [C[0] + x, C[1] + y, C[2] + z];
}

function earMapRight(d) {
  const E = STAND_IN_LAYOUT.ear;
  // a rounded disc: nearly uniform thickness, rounded rim; slightly wider at the top
  const hh = d[1];
  const w = E.halfWidth * d[0] * (1 + 0.12 * hh);
  const h = E.halfHeight * hh;
  const n = E.halfThickness * spow(d[2], 0.25) + E.cup * ((w / E.halfWidth) ** 2 + 0.5 * (h / E.halfHeight) ** 2);
  // ear frame: (uW, Y, uN) is right-handed, so the map keeps the orientation of the sphere
  return [
    E.center[0] + w * E.uW[0] + n * E.uN[0],
    E.center[1] + h,
    E.center[2] + w * E.uW[2] + n * E.uN[2],
  ];
}

function neckMap(d) {
  const { center: C, radii: R } = STAND_IN_LAYOUT.neck;
  // cylinder-like superquadric: ((x/a)^2 + (z/c)^2)^2 + (y/b)^4 = 1
  const r2 = (d[0] / R[0]) ** 2 + (d[2] / R[2]) ** 2;
  const s = (r2 * r2 + (d[1] / R[1]) ** 4) ** -0.25;
  const x = s * d[0];
  const y = s * d[1];
  const z = s * d[2] + 0.12 * (y / R[1]); // leans forward at the top
  return [C[0] + x, C[1] + y, C[2] + z];
}

function torsoMap(d) {
  const { center: C, radii: R, bottomY } = STAND_IN_LAYOUT.torso;
  // boxy in x-y (shoulders), elliptic in z, nearly flat at the bottom (the scan is cut flat there):
  // (|x/a|^3 + g(y))^(2/3) + (z/c)^2 = 1, g(y) = |y/b|^3 above the centre, |y/bLow|^8 below.
  // F grows monotonically along the ray s*d: solve F(s*d) = 1 by bisection.
  const bLow = C[1] - bottomY;
  const F = (s) => {
    const y = s * d[1];
    const g = y > 0 ? (y / R[1]) ** 3 : (-y / bLow) ** 8;
    return (Math.abs((s * d[0]) / R[0]) ** 3 + g) ** (2 / 3) + ((s * d[2]) / R[2]) ** 2;
  };
  let lo = 0;
  let hi = Math.max(R[0], R[1], R[2], bLow) * 1.01;
  for (let i = 0; i < 48; i++) {
    const mid = 0.5 * (lo + hi);
    if (F(mid) < 1) lo = mid;
    else hi = mid;
  }
  const s = 0.5 * (lo + hi);
  const x = s * d[0];
  let y = s * d[1];
  let z = s * d[2];
  // trapezius: the top rises towards the neck; the shoulders round off front to back
  const fx = Math.min(1, Math.abs(x) / R[0]);
  y += 0.45 * Math.max(0, d[1]) * (1 - fx * fx);
  z *= 1 - 0.35 * fx ** 4;
  return [C[0] + x, C[1] + y, C[2] + z];
}

/**
 * The separate parts (each closed, indexed), before merging: useful for tests and debugging.
 * @returns {{ head: object, earRight: object, earLeft: object, neck: object, torso: object }}
 *   plain arrays { positions, normals, uvs, tangents, indices } per part
 */
export function createStandInParts() {
  const earRight = tessellate(earMapRight, 40, 24);
  return {
    head: tessellate(headMap, 112, 88),
    earRight,
    earLeft: mirrorX(earRight),
    neck: tessellate(neckMap, 48, 24),
    torso: tessellate(torsoMap, 72, 36),
  };
}

/**
 * Procedural head-and-shoulders bust in the frame of LeePerrySmith.glb.
 * @returns {BufferGeometry} indexed, with position, normal, uv and tangent (vec4) attributes
 */
export function createStandInBust() {
  const p = createStandInParts();
  return toGeometry([p.head, p.earRight, p.earLeft, p.neck, p.torso], 'StandInBust');
}

// ---------------------------------------------------------------------------------------------
// textures


/** Tileable value noise on an n x n lattice (period = texture size), smooth interpolation. */
function makeValueNoise(rand, cells) {
  const lattice = new Float32Array(cells * cells);
  for (let i = 0; i < lattice.length; i++) lattice[i] = rand();
  return (u, v) => {
    const x = u * cells;
    const y = v * cells;
    const x0 = Math.floor(x);
    const y0 = Math.floor(y);
    const fx = x - x0;
    const fy = y - y0;
    const sx = fx * fx * (3 - 2 * fx);
    const sy = fy * fy * (3 - 2 * fy);
    const at = (i, j) => lattice[(((j % cells) + cells) % cells) * cells + (((i % cells) + cells) % cells)];
    const a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * sx;
    const b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * sx;
    return a + (b - a) * sy; // [0, 1]
  };
}

function makeTexture(data, size, colorSpace) {
  const t = new DataTexture(data, size, size, RGBAFormat, UnsignedByteType);
  t.wrapS = RepeatWrapping;
  t.wrapT = RepeatWrapping;
  t.magFilter = LinearFilter;
  t.minFilter = LinearMipmapLinearFilter;
  t.generateMipmaps = true;
  t.colorSpace = colorSpace;
  t.needsUpdate = true;
  return t;
}

const toByte = (x) => Math.max(0, Math.min(255, Math.round(x * 255)));

/**
 * Procedural skin textures for the stand-in (tileable, deterministic).
 * @param {{ size?: number, seed?: number }} [opts]
 * @returns {{ map: DataTexture, normalMap: DataTexture, specularMap: DataTexture }}
 *   map: sRGB skin colour with slight blotchy variation; normalMap: tangent-space, flat-ish with
 *   fine pores (linear); specularMap: grey specular level in RGB (alpha 1), linear
 */
export function createStandInTextures({ size = 256, seed = 0x5e55 } = {}) {
  const rand = mulberry32(seed);
  const low = makeValueNoise(rand, 8);
  const mid = makeValueNoise(rand, 32);
  const blotch = makeValueNoise(rand, 16);
  const fine = makeValueNoise(rand, 128);
  const pores = makeValueNoise(rand, 64);

  const n = size * size;
  const colour = new Uint8Array(n * 4);
  const normal = new Uint8Array(n * 4);
  const spec = new Uint8Array(n * 4);
  const height = new Float32Array(n);

  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const u = (i + 0.5) / size;
      const v = (j + 0.5) / size;
      const k = j * size + i;
      // pores: small pits where the pore noise is high, on top of fine roughness
      const pore = smoothstep(0.72, 0.95, pores(u, v));
      height[k] = 0.6 * fine(u, v) - pore;

      // colour (sRGB): warm light skin, low-frequency tone variation, faint red blotches, darker pores
      const tone = 0.94 + 0.08 * (low(u, v) - 0.5) + 0.04 * (mid(u, v) - 0.5);
      const red = 0.035 * smoothstep(0.55, 0.9, blotch(u, v));
      const dark = 1 - 0.05 * pore;
      colour[k * 4 + 0] = toByte((0.87 + red) * tone * dark);
      colour[k * 4 + 1] = toByte((0.67 - 0.5 * red) * tone * dark);
      colour[k * 4 + 2] = toByte((0.58 - 0.4 * red) * tone * dark);
      colour[k * 4 + 3] = 255;

      // specular level: around 0.35, oilier patches, none in the pores
      const s = (0.3 + 0.15 * low(v, u) + 0.1 * (mid(v, u) - 0.5)) * (1 - 0.3 * pore);
      spec[k * 4 + 0] = spec[k * 4 + 1] = spec[k * 4 + 2] = toByte(s);
      spec[k * 4 + 3] = 255;
    }
  }

  // tangent-space normals from the height field (central differences, wrapping)
  const strength = 0.35;
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const h = (ii, jj) => height[((jj + size) % size) * size + ((ii + size) % size)];
      const dx = (h(i + 1, j) - h(i - 1, j)) * 0.5;
      const dy = (h(i, j + 1) - h(i, j - 1)) * 0.5;
      const nn = normalize([-strength * dx, -strength * dy, 1]);
      const k = (j * size + i) * 4;
      normal[k + 0] = toByte(nn[0] * 0.5 + 0.5);
      normal[k + 1] = toByte(nn[1] * 0.5 + 0.5);
      normal[k + 2] = toByte(nn[2] * 0.5 + 0.5);
      normal[k + 3] = 255;
    }
  }

  return {
    map: makeTexture(colour, size, SRGBColorSpace),
    normalMap: makeTexture(normal, size, NoColorSpace),
    specularMap: makeTexture(spec, size, NoColorSpace),
  };
}
