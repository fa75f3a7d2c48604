// Helpers the scenes share: a seeded random generator, procedural textures as DataTextures
// (no image files, so Node and Chromium see the same texels), and a lit ground.
import * as THREE from 'three';

/** A deterministic generator in [0, 1) (mulberry32). */
export function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** A checkerboard of two colours, `n` × `n` texels, sRGB. */
export function checker(n, a, b) {
  const data = new Uint8Array(n * n * 4);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const c = ((x >> 3) + (y >> 3)) % 2 ? a : b;
      data.set([...c, 255], (y * n + x) * 4);
    }
  }
  const t = new THREE.DataTexture(data, n, n);
  t.colorSpace = THREE.SRGBColorSpace;
  t.wrapS = t.wrapT = THREE.RepeatWrapping;
  t.magFilter = THREE.NearestFilter;
  t.needsUpdate = true;
  return t;
}

/** An equirectangular sky in linear floats: bright sun band, blue above, brown below. */
export function sky(width = 64, height = 32) {
  const data = new Float32Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    const v = y / (height - 1);
    for (let x = 0; x < width; x++) {
      const u = x / (width - 1);
      const up = [0.25 + 0.4 * v, 0.45 + 0.4 * v, 0.9 + 0.3 * v];
      const down = [0.35, 0.22, 0.12];
      const c = v > 0.5 ? up : down;
      const sun = Math.exp(-(((u - 0.3) * 8) ** 2) - (((v - 0.7) * 10) ** 2)) * 8;
      data.set([c[0] + sun, c[1] + sun, c[2] + sun * 0.8, 1], (y * width + x) * 4);
    }
  }
  const t = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  t.mapping = THREE.EquirectangularReflectionMapping;
  t.magFilter = THREE.LinearFilter;
  t.minFilter = THREE.LinearFilter;
  t.needsUpdate = true;
  return t;
}

/** A ground plane that receives shadows. */
export function ground(size = 20, color = 0x808080) {
  const m = new THREE.Mesh(
    new THREE.PlaneGeometry(size, size),
    new THREE.MeshStandardMaterial({ color, roughness: 0.9 }),
  );
  m.rotation.x = -Math.PI / 2;
  m.receiveShadow = true;
  return m;
}

/** A camera at `position` looking at `target`. */
export function camera(width, height, position, target = [0, 0, 0], fov = 50) {
  const c = new THREE.PerspectiveCamera(fov, width / height, 0.1, 100);
  c.position.set(...position);
  c.lookAt(...target);
  return c;
}
