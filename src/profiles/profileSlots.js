// Which profiles a frame holds and the slot each material writes (the b channel of
// src/2-scene-split/subsurfaceTarget.js). Slot 0 is the first profile in use, so a frame of one
// profile compiles the blur with PROFILE_COUNT 1 whatever the pipeline's default.

/**
 * The most profiles one pipeline blurs in a frame: 8 keeps the stacked tables (2 + FOOTPRINT_ROWS
 * rows a slot) and the per-slot uniform array small; Unity HDRP allows 15.
 */
export const MAX_PROFILES = 8;

/**
 * The distinct profiles among `profiles` (in binding order) and each material's slot.
 * @template P
 * @param {readonly P[]} profiles each bound material's profile (objects compared by identity)
 * @param {P} fallback the pipeline's profile: the one slot when no material is bound
 * @param {string} [caller] what the error names (the call that would make too many)
 * @returns {{ profiles: P[], slots: number[] }} `slots[i]` is the slot of `profiles[i]`
 */
export function profileSlots(profiles, fallback, caller = 'makeSubsurface') {
  const distinct = [];
  const slots = profiles.map((profile) => {
    let slot = distinct.indexOf(profile);
    if (slot < 0) slot = distinct.push(profile) - 1;
    return slot;
  });
  if (distinct.length > MAX_PROFILES) {
    const names = distinct.map((p) => `'${p?.name ?? p}'`).join(', ');
    throw new RangeError(`${caller}: profile: at most ${MAX_PROFILES} profiles per pipeline, got ${distinct.length} (${names})`);
  }
  return { profiles: distinct.length > 0 ? distinct : [fallback], slots };
}
