// Page (b): page (a) with SubsurfaceScattering in place of the RenderPass, the sphere's material
// made subsurface, the SpotLight as its light.
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from 'three-separable-sss';
import { createScene } from '../scene.js';

const { renderer, scene, camera, light, material } = createScene();
const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
sss.makeSubsurface(material);
const composer = new EffectComposer(renderer);
composer.addPass(sss);
composer.addPass(new OutputPass());
window.app = { renderer, composer, sss };
