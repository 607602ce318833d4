// The before/after divider over the image: a vertical line at the split, a handle to drag (mouse,
// touch, pen; arrow keys when focused) and the labels of both sides. It sets the pipeline's split
// through `onInput(fraction)` while dragging and `onCommit()` when let go (the URL is written then).

const MIN = 0.02;
const MAX = 0.98;

export class Divider {
  /**
   * @param {HTMLElement} root the #divider element (holds .divider-handle)
   * @param {{ onInput: (fraction: number) => void, onCommit: () => void }} hooks
   */
  constructor(root, { onInput, onCommit }) {
    this.root = root;
    this.handle = root.querySelector('.divider-handle');
    const clamp = (v) => Math.min(MAX, Math.max(MIN, v));
    const fractionAt = (event) => {
      const box = root.parentElement.getBoundingClientRect();
      return clamp((event.clientX - box.left) / box.width);
    };
    let dragging = null;
    const grab = (event) => {
      if (event.button !== undefined && event.button !== 0) return;
      dragging = event.pointerId;
      event.currentTarget.setPointerCapture(event.pointerId);
      root.classList.add('dragging');
      event.preventDefault();
    };
    const move = (event) => {
      if (dragging !== event.pointerId) return;
      onInput(fractionAt(event));
    };
    const release = (event) => {
      if (dragging !== event.pointerId) return;
      dragging = null;
      root.classList.remove('dragging');
      onCommit();
    };
    for (const target of [this.handle, root.querySelector('.divider-line')]) {
      target.addEventListener('pointerdown', grab);
      target.addEventListener('pointermove', move);
      target.addEventListener('pointerup', release);
      target.addEventListener('pointercancel', release);
    }
    this.handle.addEventListener('keydown', (event) => {
      const step = event.shiftKey ? 0.1 : 0.02;
      const delta = { ArrowLeft: -step, ArrowRight: step, Home: -1, End: 1 }[event.key];
      if (delta === undefined) return;
      event.preventDefault();
      onInput(clamp(this.fraction + delta));
      onCommit();
    });
    this.fraction = 0.5;
  }

  /** Puts the divider at `fraction` of the width; hidden where there is nothing to compare. */
  show(fraction, visible) {
    this.fraction = fraction;
    this.root.hidden = !visible;
    this.root.style.setProperty('--split', String(fraction));
    this.handle.setAttribute('aria-valuenow', String(Math.round(fraction * 100)));
  }
}
