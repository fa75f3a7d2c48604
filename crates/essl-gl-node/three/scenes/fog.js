// Fog: rows of columns fading into exponential-squared fog, and a linearly fogged floor.
import * as THREE from 'three';
import { camera, checker } from './common.js';

export function create(renderer, width, height) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x9fb0c0);
  scene.fog = new THREE.FogExp2(0x9fb0c0, 0.09);
  const floor = new THREE.Mesh(
    new THREE.PlaneGeometry(60, 60),
    new THREE.MeshLambertMaterial({ map: checker(128, [200, 180, 150], [90, 80, 70]) }),
  );
  floor.material.map.repeat.set(8, 8);
  floor.rotation.x = -Math.PI / 2;
  scene.add(floor);
  const box = new THREE.BoxGeometry(0.8, 3, 0.8);
  const material = new THREE.MeshPhongMaterial({ color: 0x8844aa });
  for (let z = 0; z < 10; z++) {
    for (const x of [-2.5, 2.5]) {
      const m = new THREE.Mesh(box, material);
      m.position.set(x, 1.5, -z * 3);
      scene.add(m);
    }
  }
  scene.add(new THREE.HemisphereLight(0xffffff, 0x404040, 1.5));
  const cam = camera(width, height, [0, 1.6, 6], [0, 1.2, -10], 60);
  return { render: () => renderer.render(scene, cam) };
}
