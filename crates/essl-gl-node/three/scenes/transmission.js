// Transmission: glass-like MeshPhysicalMaterial spheres (transmission, thickness, ior,
// roughness) in front of coloured bars, which three.js renders through a mipmapped
// transmission render target.
import * as THREE from 'three';
import { camera, checker } from './common.js';

export function create(renderer, width, height) {
  renderer.toneMapping = THREE.NeutralToneMapping;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x303030);
  const wall = new THREE.Mesh(
    new THREE.PlaneGeometry(10, 6),
    new THREE.MeshBasicMaterial({ map: checker(64, [240, 80, 40], [40, 120, 240]) }),
  );
  wall.position.z = -2;
  scene.add(wall);
  [0, 0.15, 0.4].forEach((roughness, i) => {
    const glass = new THREE.Mesh(
      new THREE.SphereGeometry(0.8, 48, 24),
      new THREE.MeshPhysicalMaterial({
        color: 0xffffff,
        transmission: 1,
        thickness: 1.2,
        ior: 1.5,
        roughness,
        metalness: 0,
      }),
    );
    glass.position.set((i - 1) * 2, 0, 0);
    scene.add(glass);
  });
  scene.add(new THREE.AmbientLight(0xffffff, 1));
  const light = new THREE.DirectionalLight(0xffffff, 2);
  light.position.set(2, 3, 4);
  scene.add(light);
  const cam = camera(width, height, [0, 0, 6]);
  return { render: () => renderer.render(scene, cam) };
}
