// The blur's floor (browser side, a bench row): two full-screen passes, horizontal then vertical,
// that do what any 17-tap separable blur must do and nothing more: per subsurface pixel (the mask
// as the blur sees it, alpha not 0, on the same scene split) 17 texel fetches of the light along the axis,
// summed with equal weights. No depth, no profile, no renormalisation: what is left of the real
// blur's time above this is the cost of its sampling model.
import { FloatType, ShaderMaterial, WebGLRenderTarget } from 'three';
import { FullScreenQuad } from 'three/addons/postprocessing/Pass.js';

export const FLOOR_TAPS = 17;

const fragmentShader = /* glsl */ `
uniform sampler2D tDiffuse;
uniform ivec2 axis;
uniform ivec2 last; // resolution - 1
void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	vec4 centre = texelFetch( tDiffuse, pixel, 0 );
	if ( centre.a == 0.0 ) { gl_FragColor = centre; return; }
	vec3 sum = vec3( 0.0 );
	for ( int i = - ( TAPS / 2 ); i <= TAPS / 2; i ++ ) {
		sum += texelFetch( tDiffuse, clamp( pixel + i * axis, ivec2( 0 ), last ), 0 ).rgb;
	}
	gl_FragColor = vec4( sum / float( TAPS ), centre.a );
}`;

const vertexShader = /* glsl */ `
void main() { gl_Position = vec4( position.xy, 0.0, 1.0 ); }`;

export class FetchFloor {
  /** @param {import('/src/index.js').SubsurfaceScattering} sss the pipeline whose scene split it reads */
  constructor(sss) {
    this.sss = sss;
    const material = (axis) => new ShaderMaterial({
      defines: { TAPS: FLOOR_TAPS },
      uniforms: { tDiffuse: { value: null }, axis: { value: axis }, last: { value: [0, 0] } },
      vertexShader, fragmentShader, depthTest: false, depthWrite: false,
    });
    this.horizontal = new FullScreenQuad(material([1, 0]));
    this.vertical = new FullScreenQuad(material([0, 1]));
    // The format the blur's own light between its passes has (32-bit float: it carries the depth).
    this.targets = [0, 1].map(() => new WebGLRenderTarget(1, 1, { type: FloatType, depthBuffer: false }));
  }

  /**
   * Both passes over the last scene split, each timed as a stage of `timer` ('floorH', 'floorV').
   * @param {import('three').WebGLRenderer} renderer
   * @param {{ begin(stage: string): void, end(stage: string): void }} timer
   */
  render(renderer, timer) {
    const { renderTarget } = this.sss._scenePass;
    const { width, height } = renderTarget;
    for (const t of this.targets) if (t.width !== width || t.height !== height) t.setSize(width, height);
    const current = renderer.getRenderTarget();
    const passes = [['floorH', this.horizontal, this.sss._scenePass.diffuseTexture, this.targets[0]], ['floorV', this.vertical, this.targets[0].texture, this.targets[1]]];
    try {
      for (const [stage, quad, input, output] of passes) {
        quad.material.uniforms.tDiffuse.value = input;
        quad.material.uniforms.last.value = [width - 1, height - 1];
        renderer.setRenderTarget(output);
        timer.begin(stage);
        quad.render(renderer);
        timer.end(stage);
      }
    } finally {
      renderer.setRenderTarget(current);
    }
  }

  dispose() {
    for (const quad of [this.horizontal, this.vertical]) {
      quad.material.dispose();
      quad.dispose();
    }
    for (const t of this.targets) t.dispose();
  }
}
