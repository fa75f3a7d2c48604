// InstancedMesh: 400 boxes with their own matrices and colours.
import * as THREE from 'three';
import { camera, random } from './common.js';

export function create(renderer, width, height) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x111111);
  const rnd = random(7);
  const count = 400;
  const mesh = new THREE.InstancedMesh(
    new THREE.BoxGeometry(0.3, 0.3, 0.3),
    new THREE.MeshLambertMaterial(),
    count,
  );
  const m = new THREE.Matrix4();
  const q = new THREE.Quaternion();
  const e = new THREE.Euler();
  for (let i = 0; i < count; i++) {
    e.set(rnd() * 6, rnd() * 6, 0);
    q.setFromEuler(e);
    const s = 0.5 + rnd();
    m.compose(new THREE.Vector3((rnd() - 0.5) * 8, (rnd() - 0.5) * 6, (rnd() - 0.5) * 6), q, new THREE.Vector3(s, s, s));
    mesh.setMatrixAt(i, m);
    mesh.setColorAt(i, new THREE.Color().setHSL(rnd(), 0.7, 0.5));
  }
  scene.add(mesh);
  scene.add(new THREE.AmbientLight(0xffffff, 0.5));
  const light = new THREE.DirectionalLight(0xffffff, 2);
  light.position.set(1, 2, 3);
  scene.add(light);
  const cam = camera(width, height, [0, 0, 9]);
  return { render: () => renderer.render(scene, cam) };
}
