// What the light depth map holds on test/pages/lab.js's lightDepthCards, by lab.cardDepths' names:
// distances along the light's axis, the wall at 10, the cards at 7 where they are surfaces to the
// light. Both light depth targets are held to it (the WebGL path's and the WebGPU node's).
export const CARD_DEPTHS = Object.freeze({
  mapCut: 10, mapKept: 7, alphaMapCut: 10, alphaMapKept: 7, clipped: 10, unclipped: 7, glass: 10, glassToo: 10,
});

// The entry cosine |N·L| there (lab.cardCosines): a card facing the light 1, one turned 60° from it
// 0.5, and the same card without normals 1 (both light depth targets let a mesh without normals
// take the whole light in).
export const CARD_COSINES = Object.freeze({ tilted: 0.5, tiltedNoNormals: 1, unclipped: 1 });
