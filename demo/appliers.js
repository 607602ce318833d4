// How the demo's state (demo/state.js) reaches the scene and the pipeline: the state keys in groups,
// and one applier per group (a group is applied whole when one of its keys changes).
import { getProfile } from '../src/index.js';
import { computeKernel } from '../src/stages.js';
import { setLightDirection } from './headScene.js';
import { shotCamera } from './framing.js';
import { drawKernel } from './kernelPlot.js';

/** Nothing to compare: scattering off, the divider at an edge, or a view the split does not affect. */
const dividerVisible = (state) => state.sss && state.split > 0 && state.split < 1 && ['final', 'diffuse', 'kernel'].includes(state.view);

export const KERNEL_KEYS = ['profile', 'method', 'samples', 'strength', 'falloff', 'groups'];

/** Which of the appliers (createAppliers) a state key belongs to. */
export function groupOf(key) {
  if (KERNEL_KEYS.includes(key)) return 'kernel';
  if (['width', 'translucency', 'shrink'].includes(key)) return 'material';
  if (key === 'depthThreshold') return 'followSurface';
  if (key === 'roughness') return 'specular';
  if (key === 'shot') return 'camera';
  if (key.startsWith('light') && key !== 'lightDepthSize') return 'light';
  return key;
}

/**
 * How each group of state keys reaches the scene and the pipeline.
 * @param {object} demo the page's parts (demo/main.js): state, sss, material, marble and foliage (the pieces), rig, light, camera,
 *   controls, divider, resize(), and the kernel plot's canvas and the shot buttons
 */
export function createAppliers(demo) {
  const { state, sss, material, marble, foliage, rig, light, camera, controls, kernelCanvas, shotButtons } = demo;
  const showDivider = () => demo.divider.show(state.split, dividerVisible(state));

  return {
    sss: () => {
      sss.scattering = state.sss;
      showDivider();
    },
    kernel: () => {
      // A count of groups is for method 'footprint' alone: 'auto' holds for every method while the method changes.
      sss.kernelGroups = 'auto';
      Object.assign(sss, {
        profile: state.profile, method: state.method, samples: state.samples,
        strength: [...state.strength], falloff: [...state.falloff],
      });
      sss.kernelGroups = state.method === 'footprint' ? state.groups : 'auto';
    },
    // The marble piece, with a profile of its own in the head's pipeline (every method of the
    // demo blurs several per frame). Hidden, it is unbound: the frame holds one profile, as before.
    marble: () => {
      marble.visible = state.marble;
      if (state.marble) sss.makeSubsurface(marble.material, { profile: 'marble' });
      else sss.removeSubsurface(marble.material);
    },
    // The plant's leaves scatter about as far as a leaf is thick (a few tenths of a millimetre), in the
    // head's pipeline and profile; their glow through no thickness is the leaf's colour, whatever
    // the profile. Hidden, they are unbound.
    foliage: () => {
      foliage.piece.visible = state.foliage;
      if (state.foliage) sss.makeSubsurface(foliage.material, { widthMm: 0.25 });
      else sss.removeSubsurface(foliage.material);
    },
    material: () => sss.makeSubsurface(material, { widthMm: state.width, translucency: state.translucency, shrinkMm: state.shrink }),
    followSurface: () => Object.assign(sss, { followSurface: state.followSurface, depthThresholdMm: state.depthThreshold }),
    transmittance: () => { sss.transmittance = state.transmittance; },
    lightDepthSize: () => { sss.lightDepthSize = state.lightDepthSize; },
    specular: () => { material.specularIntensity = state.specular; material.roughness = state.roughness; },
    light: () => {
      setLightDirection(rig, state.lightAzimuth, state.lightElevation);
      light.intensity = state.lightIntensity;
      light.color.set(state.lightColor);
    },
    // The ear's point light joins the key light in the pipeline's list (each gets its own thickness map).
    pointLight: () => {
      rig.pointLight.visible = state.pointLight;
      sss.light = state.pointLight ? [light, rig.pointLight] : light;
    },
    split: () => {
      sss.split = state.split;
      showDivider();
    },
    view: () => {
      // Depth view: white at the camera, black 30 units (1.5 m) away, past the head at any zoom.
      Object.assign(sss, { debugView: state.view === 'kernel' ? 'final' : state.view, debugDepthRange: 30 });
      kernelCanvas.hidden = state.view !== 'kernel';
      if (state.view === 'kernel') drawKernel(kernelCanvas, kernelOf(sss), state.method === 'reference' ? null : getProfile(state.profile));
      showDivider();
    },
    resolutionScale: () => demo.resize(),
    camera: () => {
      const [x, y, z, tx, ty, tz] = state.camera ?? shotCamera(state.shot, camera.aspect, camera.fov);
      camera.position.set(x, y, z);
      controls.target.set(tx, ty, tz);
      controls.update();
      for (const button of shotButtons) button.setAttribute('aria-pressed', String(!state.camera && button.dataset.shot === state.shot));
    },
  };
}

/** The separable kernel the pipeline's last frame blurred with (its method's, at the frame's taps). */
function kernelOf(sss) {
  const method = sss.method === 'reference' ? 'reference' : 'marginal';
  return computeKernel({ profile: sss.profile, method, samples: sss.plan.samples, strength: sss.strength, falloff: sss.falloff });
}
