// Every light type; the directional, spot and point lights cast PCF shadows.
import * as THREE from 'three';
import { RectAreaLightUniformsLib } from 'three/addons/lights/RectAreaLightUniformsLib.js';
import { camera, ground } from './common.js';

export function lightsScene(renderer, width, height, shadowType) {
  renderer.shadowMap.enabled = true;
  renderer.shadowMap.type = shadowType;
  RectAreaLightUniformsLib.init();
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x101018);
  scene.add(ground(16));
  const materials = [
    new THREE.MeshStandardMaterial({ color: 0xd04030, roughness: 0.4 }),
    new THREE.MeshPhongMaterial({ color: 0x30a050, shininess: 60 }),
    new THREE.MeshLambertMaterial({ color: 0x3060d0 }),
  ];
  const geometries = [
    new THREE.BoxGeometry(1.2, 1.2, 1.2),
    new THREE.SphereGeometry(0.8, 32, 16),
    new THREE.TorusKnotGeometry(0.5, 0.18, 96, 12),
  ];
  geometries.forEach((g, i) => {
    const m = new THREE.Mesh(g, materials[i]);
    m.position.set((i - 1) * 2.6, 1, 0);
    m.rotation.set(0.3 * i, 0.5 + 0.4 * i, 0);
    m.castShadow = true;
    m.receiveShadow = true;
    scene.add(m);
  });
  scene.add(new THREE.AmbientLight(0x404050, 0.4));
  scene.add(new THREE.HemisphereLight(0x8090ff, 0x302010, 0.4));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(4, 8, 3);
  sun.castShadow = true;
  sun.shadow.mapSize.set(512, 512);
  Object.assign(sun.shadow.camera, { left: -6, right: 6, top: 6, bottom: -6, near: 1, far: 20 });
  sun.shadow.bias = -0.001;
  scene.add(sun);
  const spot = new THREE.SpotLight(0xffd080, 40, 20, Math.PI / 7, 0.3, 2);
  spot.position.set(-4, 6, 4);
  spot.target.position.set(-2.6, 0, 0);
  spot.castShadow = true;
  spot.shadow.mapSize.set(512, 512);
  spot.shadow.bias = -0.001;
  scene.add(spot, spot.target);
  const point = new THREE.PointLight(0x80c0ff, 20, 12, 2);
  point.position.set(2.5, 3, 2);
  point.castShadow = shadowType !== THREE.VSMShadowMap;
  point.shadow.mapSize.set(256, 256);
  point.shadow.bias = -0.002;
  scene.add(point);
  const rect = new THREE.RectAreaLight(0xff40ff, 3, 3, 1);
  rect.position.set(0, 2.5, -3);
  rect.lookAt(0, 0, 0);
  scene.add(rect);
  const cam = camera(width, height, [0, 5, 9], [0, 0.8, 0]);
  return { render: () => renderer.render(scene, cam) };
}

export function create(renderer, width, height) {
  return lightsScene(renderer, width, height, THREE.PCFShadowMap);
}
