// PBR: a grid of MeshPhysicalMaterial spheres (metalness × roughness) lit only by an
// environment map prefiltered from an equirectangular DataTexture (PMREMGenerator).
import * as THREE from 'three';
import { camera, sky } from './common.js';

export function create(renderer, width, height) {
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  const scene = new THREE.Scene();
  const pmrem = new THREE.PMREMGenerator(renderer);
  const env = pmrem.fromEquirectangular(sky()).texture;
  scene.environment = env;
  scene.background = env;
  scene.backgroundBlurriness = 0.5;
  const geometry = new THREE.SphereGeometry(0.42, 32, 16);
  for (let i = 0; i < 4; i++) {
    for (let j = 0; j < 4; j++) {
      const m = new THREE.Mesh(
        geometry,
        new THREE.MeshPhysicalMaterial({
          color: new THREE.Color().setHSL(j / 4, 0.6, 0.55),
          metalness: i / 3,
          roughness: 0.05 + j / 3.5,
          clearcoat: i === 3 ? 1 : 0,
        }),
      );
      m.position.set((j - 1.5) * 1, (i - 1.5) * 1, 0);
      scene.add(m);
    }
  }
  const cam = camera(width, height, [0, 0, 5.5], [0, 0, 0], 45);
  return { render: () => renderer.render(scene, cam) };
}
