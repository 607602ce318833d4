// What the compose pass can show: the final image or one of its ingredients, and what each view
// needs the subsurface materials to write into the diffuse attachment. The compose shader compares
// the views by name (DEBUG_VIEW_MASK, ...: src/support/glsl.js's enumDefines), never by position.

/**
 * What the compose can show (setDebugView).
 * @typedef {'final'|'diffuse'|'specular'|'depth'|'mask'|'thickness'|'transmittance'} DebugView
 */

/**
 * The accepted debug views.
 * @type {readonly DebugView[]}
 */
export const DEBUG_VIEWS = Object.freeze(['final', 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance']);

/**
 * The same views by name, in the style of three's GTAOPass.OUTPUT: DEBUG_VIEW.MASK === 'mask'.
 * @type {Readonly<{ [V in DebugView as Uppercase<V>]: V }>}
 */
export const DEBUG_VIEW = Object.freeze(Object.fromEntries(DEBUG_VIEWS.map((view) => [view.toUpperCase(), view])));

/**
 * What the diffuse attachment receives: the diffuse light, or one ingredient for a debug view
 * (the WebGL material hook's and the WebGPU node material's `sssDebugOutput`, by position).
 * @type {readonly ('diffuse'|'transmittance'|'thickness')[]}
 */
export const MATERIAL_OUTPUTS = Object.freeze(['diffuse', 'transmittance', 'thickness']);

/**
 * What the materials must write into the diffuse attachment for `view` (one of the material
 * hook's MATERIAL_OUTPUTS): the thickness and transmittance views replace the diffuse light with
 * that ingredient; every other view needs the diffuse light itself.
 * @param {DebugView} view one of DEBUG_VIEWS
 * @returns {'diffuse'|'thickness'|'transmittance'}
 */
export function materialOutputOf(view) {
  return view === DEBUG_VIEW.THICKNESS || view === DEBUG_VIEW.TRANSMITTANCE ? view : 'diffuse';
}
