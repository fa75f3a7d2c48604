// The other material families: normal, depth, matcap (from a DataTexture), toon with a
// gradient map, wireframe, and textured Lambert with mipmaps and anisotropic filtering.
import * as THREE from 'three';
import { camera, checker } from './common.js';

function gradient() {
  const t = new THREE.DataTexture(new Uint8Array([60, 140, 220, 255]), 4, 1, THREE.RedFormat);
  t.minFilter = t.magFilter = THREE.NearestFilter;
  t.needsUpdate = true;
  return t;
}

function matcap(n) {
  const data = new Uint8Array(n * n * 4);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const u = (x / (n - 1)) * 2 - 1;
      const v = (y / (n - 1)) * 2 - 1;
      const l = Math.max(0, 1 - u * u - v * v);
      data.set([Math.round(80 + 175 * l), Math.round(60 + 120 * l * (v + 1) / 2), 120, 255], (y * n + x) * 4);
    }
  }
  const t = new THREE.DataTexture(data, n, n);
  t.colorSpace = THREE.SRGBColorSpace;
  t.magFilter = THREE.LinearFilter;
  t.needsUpdate = true;
  return t;
}

export function create(renderer, width, height) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x181818);
  const tex = checker(64, [255, 255, 255], [30, 30, 30]);
  tex.magFilter = THREE.LinearFilter;
  tex.minFilter = THREE.LinearMipmapLinearFilter;
  tex.anisotropy = 4;
  tex.repeat.set(4, 4);
  const materials = [
    new THREE.MeshNormalMaterial(),
    new THREE.MeshDepthMaterial(),
    new THREE.MeshMatcapMaterial({ matcap: matcap(64) }),
    new THREE.MeshToonMaterial({ color: 0x44aaff, gradientMap: gradient() }),
    new THREE.MeshBasicMaterial({ color: 0xffff00, wireframe: true }),
    new THREE.MeshLambertMaterial({ map: tex }),
  ];
  const geometry = new THREE.TorusGeometry(0.55, 0.22, 24, 48);
  materials.forEach((material, i) => {
    const m = new THREE.Mesh(geometry, material);
    m.position.set((i % 3 - 1) * 1.9, i < 3 ? 0.9 : -0.9, 0);
    m.rotation.set(0.6, 0.4 * i, 0);
    scene.add(m);
  });
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(12, 12), new THREE.MeshLambertMaterial({ map: tex }));
  floor.rotation.x = -Math.PI / 2.3;
  floor.position.set(0, -2, -3);
  scene.add(floor);
  scene.add(new THREE.AmbientLight(0xffffff, 0.6));
  const light = new THREE.DirectionalLight(0xffffff, 2);
  light.position.set(1, 2, 3);
  scene.add(light);
  const cam = camera(width, height, [0, 0, 6.5]);
  cam.near = 3;
  cam.far = 12;
  cam.updateProjectionMatrix();
  return { render: () => renderer.render(scene, cam) };
}
