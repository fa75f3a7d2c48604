// Points (PointsMaterial with size attenuation and vertex colours), lines and line
// segments, and sprites with a DataTexture map.
import * as THREE from 'three';
import { camera, random } from './common.js';

function dot(n) {
  const data = new Uint8Array(n * n * 4);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const d = Math.hypot(x - n / 2 + 0.5, y - n / 2 + 0.5) / (n / 2);
      const a = Math.max(0, 1 - d);
      data.set([255, 230, 150, Math.round(255 * a)], (y * n + x) * 4);
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
  scene.background = new THREE.Color(0x050510);
  const rnd = random(11);
  const positions = [];
  const colors = [];
  for (let i = 0; i < 600; i++) {
    positions.push((rnd() - 0.5) * 8, (rnd() - 0.5) * 5, (rnd() - 0.5) * 4);
    colors.push(rnd(), rnd(), 1);
  }
  const pg = new THREE.BufferGeometry();
  pg.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  pg.setAttribute('color', new THREE.Float32BufferAttribute(colors, 3));
  scene.add(new THREE.Points(pg, new THREE.PointsMaterial({ size: 0.12, vertexColors: true })));
  const spiral = [];
  for (let i = 0; i < 200; i++) {
    const a = i * 0.15;
    spiral.push(Math.cos(a) * (0.5 + i * 0.012), -2 + i * 0.02, Math.sin(a) * (0.5 + i * 0.012));
  }
  const lg = new THREE.BufferGeometry().setFromPoints(spiral.reduce((acc, _, i, arr) => (i % 3 === 0 ? [...acc, new THREE.Vector3(arr[i], arr[i + 1], arr[i + 2])] : acc), []));
  scene.add(new THREE.Line(lg, new THREE.LineBasicMaterial({ color: 0x66ff66 })));
  const grid = new THREE.GridHelper(8, 16, 0xff4444, 0x444488);
  grid.position.y = -2.2;
  scene.add(grid);
  const map = dot(32);
  for (let i = 0; i < 12; i++) {
    const s = new THREE.Sprite(new THREE.SpriteMaterial({ map, color: new THREE.Color().setHSL(i / 12, 0.6, 0.7) }));
    s.position.set((i % 4) * 1.8 - 2.7, Math.floor(i / 4) * 1.4 - 1, 1);
    s.scale.setScalar(0.8);
    scene.add(s);
  }
  const cam = camera(width, height, [0, 0.5, 8]);
  return { render: () => renderer.render(scene, cam) };
}
