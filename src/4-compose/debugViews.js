// What the compose pass can show, and what each view needs the materials to write; the shader
// compares views by name (src/support/glsl.js's enumDefines).

/**
 * What the compose can show (setDebugView).
 * @typedef {'final'|'diffuse'|'specular'|'depth'|'mask'|'thickness'|'transmittance'} DebugView
 */

/**
 * @type {readonly DebugView[]}
 */
export const DEBUG_VIEWS = Object.freeze(['final', 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance']);

/**
 * The same views by name, in the style of three's GTAOPass.OUTPUT: DEBUG_VIEW.MASK === 'mask'.
 * @type {Readonly<{ [V in DebugView as Uppercase<V>]: V }>}
 */
export const DEBUG_VIEW = Object.freeze(Object.fromEntries(DEBUG_VIEWS.map((view) => [view.toUpperCase(), view])));

/**
 * What the diffuse attachment receives (`sssDebugOutput` of both material hooks, by position).
 * @type {readonly ('diffuse'|'transmittance'|'thickness')[]}
 */
export const MATERIAL_OUTPUTS = Object.freeze(['diffuse', 'transmittance', 'thickness']);

/**
 * What the materials must write into the diffuse attachment for `view`.
 * @param {DebugView} view one of DEBUG_VIEWS
 * @returns {'diffuse'|'thickness'|'transmittance'}
 */
export function materialOutputOf(view) {
  return view === DEBUG_VIEW.THICKNESS || view === DEBUG_VIEW.TRANSMITTANCE ? view : 'diffuse';
}
