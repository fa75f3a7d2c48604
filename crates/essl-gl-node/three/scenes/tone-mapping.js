// Tone mapping and sRGB output: over-bright lights on white and coloured materials, ACES
// filmic tone mapping with exposure, output in sRGB; the left half is drawn with the
// scissor test and AgX, the right half with ACES.
import * as THREE from 'three';
import { camera } from './common.js';

export function create(renderer, width, height) {
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.toneMappingExposure = 1.4;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x000000);
  const colors = [0xffffff, 0xff2200, 0x22ff44, 0x2244ff, 0xffcc00];
  colors.forEach((c, i) => {
    const m = new THREE.Mesh(
      new THREE.SphereGeometry(0.55, 32, 16),
      new THREE.MeshStandardMaterial({ color: c, roughness: 0.35, emissive: c, emissiveIntensity: i * 0.6 }),
    );
    m.position.set((i - 2) * 1.25, 0, 0);
    scene.add(m);
  });
  const light = new THREE.PointLight(0xffffff, 80, 0, 2);
  light.position.set(0, 2.5, 3);
  scene.add(light);
  scene.add(new THREE.AmbientLight(0xffffff, 0.2));
  const cam = camera(width, height, [0, 0.5, 6]);
  return {
    render() {
      renderer.setScissorTest(true);
      renderer.toneMapping = THREE.AgXToneMapping;
      renderer.setScissor(0, 0, width / 2, height);
      renderer.render(scene, cam);
      renderer.toneMapping = THREE.ACESFilmicToneMapping;
      renderer.setScissor(width / 2, 0, width / 2, height);
      renderer.render(scene, cam);
      renderer.setScissorTest(false);
    },
  };
}
