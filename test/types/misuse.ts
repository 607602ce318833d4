// Deliberate misuses: each line after a `@ts-expect-error` must be a compile error.
// test/packaging/types.test.js compiles this file as it is (an unused directive would fail it) and
// with the directives removed, where it expects an error on exactly those lines.
import * as THREE from 'three';
import { SubsurfaceScattering } from 'three-separable-sss';
import { makeSubsurface, computeKernel } from 'three-separable-sss/stages';
import { SubsurfaceScatteringPass } from 'three-separable-sss/postprocessing';
import { useSubsurfaceScattering } from 'three-separable-sss/react';
import { subsurfaceMaterial } from 'three-separable-sss/webgpu';

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera();
// @ts-expect-error camera is required
new SubsurfaceScattering({ scene });
// @ts-expect-error an unknown method
new SubsurfaceScattering({ scene, camera, method: 'fast' });
// @ts-expect-error a misspelt profile
new SubsurfaceScattering({ scene, camera, profile: 'skni' });
// @ts-expect-error followSurface is one of 'off' | 'drop' | 'lerp'
new SubsurfaceScattering({ scene, camera, followSurface: 'snap' });
// @ts-expect-error samples is a number or 'auto'
new SubsurfaceScattering({ scene, camera, samples: '17' });
// @ts-expect-error a hemisphere light gives no transmittance
new SubsurfaceScattering({ scene, camera, light: new THREE.HemisphereLight() });
const sss = new SubsurfaceScattering({ scene, camera });
// @ts-expect-error an unknown debug view
sss.debugView = 'masks';
// @ts-expect-error debugDepthRange is a number
sss.debugDepthRange = '10';
// @ts-expect-error only MeshStandardMaterial and MeshPhysicalMaterial scatter
sss.makeSubsurface(new THREE.MeshBasicMaterial());
// @ts-expect-error widthMm is a number
sss.makeSubsurface(new THREE.MeshStandardMaterial(), { widthMm: '1' });
// @ts-expect-error split is a fraction
sss.split = 'half';
// @ts-expect-error multisampling is a number or 'auto'
sss.multisampling = 'on';
// @ts-expect-error scattering is a boolean (at run time too: 'no' is a TypeError, not true)
sss.scattering = 'no';
// @ts-expect-error enabled is a boolean
sss.enabled = 'no';
// @ts-expect-error the kernel's method is one of the three
sss.method = 'gauss';
// @ts-expect-error samples is an odd count or 'auto'
sss.samples = 'many';
// @ts-expect-error computeKernel's method is 'reference' or 'marginal'
computeKernel({ method: 'footprint' });
// @ts-expect-error makeSubsurface needs a material
makeSubsurface();
// @ts-expect-error the pmndrs pass takes the same options
new SubsurfaceScatteringPass({ scene, camera, method: 'fast' });
// @ts-expect-error antialias is a sample count
useSubsurfaceScattering({ antialias: true });
// @ts-expect-error subsurfaceMaterial takes a MeshStandardMaterial or MeshPhysicalMaterial (or its node version)
subsurfaceMaterial(new THREE.MeshBasicMaterial());
class Tinted extends THREE.MeshStandardMaterial { tint(): void {} }
const tinted = new THREE.Mesh(new THREE.BoxGeometry(), new Tinted());
// @ts-expect-error the node material is three's kind of material, not the subclass (its methods are not carried over)
tinted.material = subsurfaceMaterial(tinted.material);
