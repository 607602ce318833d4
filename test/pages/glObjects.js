// Counts the live WebGL objects of every WebGL2 context on the page: wraps the context prototype's
// create*/delete* (and fenceSync/deleteSync) before any other script runs (reliability.html loads
// this classic script first). window.glObjects.live() is { Buffer: n, Texture: n, ... }, created
// minus deleted; an object deleted twice, or a null one, counts once or not at all.
(() => {
  const proto = WebGL2RenderingContext.prototype;
  const live = {};
  const tracked = new WeakMap(); // object → kind
  const kinds = ['Buffer', 'Framebuffer', 'Program', 'Renderbuffer', 'Shader', 'Texture', 'VertexArray', 'Query', 'Sampler', 'TransformFeedback'];
  const wrap = (createName, deleteName, kind) => {
    const create = proto[createName];
    const remove = proto[deleteName];
    proto[createName] = function (...args) {
      const object = create.apply(this, args);
      if (object) {
        tracked.set(object, kind);
        live[kind] = (live[kind] ?? 0) + 1;
      }
      return object;
    };
    proto[deleteName] = function (object) {
      if (object && tracked.get(object) === kind) {
        tracked.delete(object);
        live[kind] -= 1;
      }
      return remove.call(this, object);
    };
  };
  for (const kind of kinds) wrap(`create${kind}`, `delete${kind}`, kind);
  wrap('fenceSync', 'deleteSync', 'Sync');
  window.glObjects = {
    /** Live objects by kind (kinds never created are 0). */
    live() {
      return Object.fromEntries([...kinds, 'Sync'].map((kind) => [kind, live[kind] ?? 0]));
    },
    /** Live objects of every kind together. */
    total() {
      return Object.values(live).reduce((sum, n) => sum + n, 0);
    },
  };
})();
