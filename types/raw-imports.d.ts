// Vite's `?raw` imports (the GLSL files under shaders/) are strings; the library build inlines them.
declare module '*?raw' {
  const source: string;
  export default source;
}
