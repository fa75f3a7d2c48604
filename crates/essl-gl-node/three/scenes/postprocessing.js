// A post-processing chain: EffectComposer with a RenderPass, a ShaderPass (vignette and a
// colour shift) and an OutputPass (tone mapping and sRGB).
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { camera, checker } from './common.js';

const Vignette = {
  uniforms: { tDiffuse: { value: null }, strength: { value: 0.9 } },
  vertexShader: `varying vec2 vUv; void main() { vUv = uv; gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }`,
  fragmentShader: `uniform sampler2D tDiffuse; uniform float strength; varying vec2 vUv;
    void main() {
      vec4 c = texture2D(tDiffuse, vUv);
      float d = distance(vUv, vec2(0.5));
      c.rgb *= 1.0 - strength * d * d;
      c.rgb = vec3(c.r * 1.1, c.g, c.b * 0.9);
      gl_FragColor = c;
    }`,
};

export function create(renderer, width, height) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x406080);
  const floor = new THREE.Mesh(
    new THREE.PlaneGeometry(10, 10),
    new THREE.MeshStandardMaterial({ map: checker(64, [220, 220, 220], [60, 60, 60]) }),
  );
  floor.rotation.x = -Math.PI / 2;
  scene.add(floor);
  const knot = new THREE.Mesh(
    new THREE.TorusKnotGeometry(0.8, 0.3, 128, 16),
    new THREE.MeshStandardMaterial({ color: 0xffaa33, roughness: 0.3, metalness: 0.2 }),
  );
  knot.position.y = 1.4;
  scene.add(knot);
  scene.add(new THREE.AmbientLight(0xffffff, 0.3));
  const light = new THREE.DirectionalLight(0xffffff, 2);
  light.position.set(3, 5, 2);
  scene.add(light);
  const cam = camera(width, height, [0, 3, 6], [0, 1, 0]);
  const composer = new EffectComposer(renderer);
  composer.setSize(width, height);
  composer.addPass(new RenderPass(scene, cam));
  composer.addPass(new ShaderPass(Vignette));
  composer.addPass(new OutputPass());
  return { render: () => composer.render() };
}
