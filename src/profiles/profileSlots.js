// Several profiles in one pipeline, pure: which profiles a frame holds and the index each material
// writes into the multi-target (src/2-scene-split/subsurfaceTarget.js, the surface's b channel).
// Slot 0 is the first profile in use, so a frame of one profile has one slot whatever the
// pipeline's default is; the blur is then compiled as without this feature (PROFILE_COUNT 1).
// test/node/profiles/profileSlots.test.js.

/**
 * The most profiles one pipeline blurs in a frame. Each slot costs a 2-row block of the stacked
 * profile table and FOOTPRINT_ROWS rows of the stacked footprint table; 8 keeps both small (8 × 81
 * rows) and the per-slot uniform array short; Unity HDRP allows 15.
 */
export const MAX_PROFILES = 8;

/**
 * The slots of a frame: the distinct profiles among `profiles` (each material's, in binding
 * order; the pipeline's own when none is bound), each material's slot.
 * @template P
 * @param {readonly P[]} profiles each bound material's profile (objects compared by identity)
 * @param {P} fallback the pipeline's profile: the one slot when no material is bound
 * @returns {{ profiles: P[], slots: number[] }} `slots[i]` is the slot of `profiles[i]`
 */
export function profileSlots(profiles, fallback) {
  const distinct = [];
  const slots = profiles.map((profile) => {
    let slot = distinct.indexOf(profile);
    if (slot < 0) slot = distinct.push(profile) - 1;
    return slot;
  });
  if (distinct.length > MAX_PROFILES) {
    const names = distinct.map((p) => `'${p?.name ?? p}'`).join(', ');
    throw new RangeError(`makeSubsurface: profile: at most ${MAX_PROFILES} profiles per pipeline, got ${distinct.length} (${names})`);
  }
  return { profiles: distinct.length > 0 ? distinct : [fallback], slots };
}
