// A skinned cylinder bent by posed bones, and a sphere blended towards two morph targets.
import * as THREE from 'three';
import { camera } from './common.js';

function skinnedCylinder() {
  const segments = 8;
  const height = 4;
  const geometry = new THREE.CylinderGeometry(0.35, 0.35, height, 16, segments * 4, false);
  const position = geometry.attributes.position;
  const indices = [];
  const weights = [];
  const v = new THREE.Vector3();
  for (let i = 0; i < position.count; i++) {
    v.fromBufferAttribute(position, i);
    const y = v.y + height / 2;
    const bone = Math.min(Math.floor(y / (height / segments)), segments - 1);
    const w = (y % (height / segments)) / (height / segments);
    indices.push(bone, Math.min(bone + 1, segments - 1), 0, 0);
    weights.push(1 - w, w, 0, 0);
  }
  geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(indices, 4));
  geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(weights, 4));
  const bones = [];
  let prev = null;
  for (let i = 0; i < segments; i++) {
    const b = new THREE.Bone();
    b.position.y = i === 0 ? -height / 2 : height / segments;
    if (prev) prev.add(b);
    bones.push(b);
    prev = b;
  }
  const mesh = new THREE.SkinnedMesh(
    geometry,
    new THREE.MeshStandardMaterial({ color: 0x44aa88, roughness: 0.5 }),
  );
  mesh.add(bones[0]);
  mesh.bind(new THREE.Skeleton(bones));
  bones.forEach((b, i) => {
    b.rotation.z = i === 0 ? 0 : 0.22;
    b.rotation.x = 0.05 * i;
  });
  return mesh;
}

function morphSphere() {
  const geometry = new THREE.SphereGeometry(0.9, 32, 16);
  const base = geometry.attributes.position;
  const spiky = [];
  const squashed = [];
  const v = new THREE.Vector3();
  for (let i = 0; i < base.count; i++) {
    v.fromBufferAttribute(base, i);
    const k = 1 + 0.35 * Math.sin(v.x * 9) * Math.sin(v.y * 9);
    spiky.push(v.x * k, v.y * k, v.z * k);
    squashed.push(v.x * 1.3, v.y * 0.5, v.z * 1.3);
  }
  geometry.morphAttributes.position = [
    new THREE.Float32BufferAttribute(spiky, 3),
    new THREE.Float32BufferAttribute(squashed, 3),
  ];
  const mesh = new THREE.Mesh(
    geometry,
    new THREE.MeshStandardMaterial({ color: 0xcc6633, roughness: 0.4, flatShading: true }),
  );
  mesh.morphTargetInfluences = [0.6, 0.3];
  return mesh;
}

export function create(renderer, width, height) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x202830);
  const skinned = skinnedCylinder();
  skinned.position.x = -1.5;
  scene.add(skinned);
  const morph = morphSphere();
  morph.position.x = 1.6;
  scene.add(morph);
  scene.add(new THREE.AmbientLight(0xffffff, 0.4));
  const light = new THREE.DirectionalLight(0xffffff, 2.2);
  light.position.set(2, 3, 4);
  scene.add(light);
  const cam = camera(width, height, [0, 0.5, 7], [0, 0.3, 0]);
  return { render: () => renderer.render(scene, cam) };
}
