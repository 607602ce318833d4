// Page (a): three + EffectComposer + RenderPass + OutputPass drawing the lit sphere.
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { createScene } from '../scene.js';

const { renderer, scene, camera } = createScene();
const composer = new EffectComposer(renderer);
composer.addPass(new RenderPass(scene, camera));
composer.addPass(new OutputPass());
window.app = { renderer, composer, sss: null };
