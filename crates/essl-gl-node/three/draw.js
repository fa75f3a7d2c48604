// Draws a scene with a WebGLRenderer on `gl`, reads it back, and times frames: shared by
// Node (essl-gl) and the browser page (Chromium).

/** Renders scene module `mod` once; its pixels (readPixels order) and 30 frame times. */
export async function drawScene(THREE, mod, gl, canvas, width, height, frames = 30) {
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
  renderer.setSize(width, height, false);
  const scene = mod.create(renderer, width, height);
  scene.render();
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const one = new Uint8Array(4);
  const times = [];
  for (let i = 0; i < frames; i++) {
    const t0 = performance.now();
    scene.render();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, one);
    times.push(performance.now() - t0);
  }
  const error = gl.getError();
  renderer.dispose();
  times.sort((a, b) => a - b);
  return { pixels, median: times[Math.floor(times.length / 2)], error };
}
