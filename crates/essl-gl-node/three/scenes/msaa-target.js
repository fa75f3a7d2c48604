// A scene rendered into a multisampled WebGLRenderTarget (4 samples), then shown on a
// screen-filling quad.
import * as THREE from 'three';
import { camera } from './common.js';

export function create(renderer, width, height) {
  const target = new THREE.WebGLRenderTarget(width, height, { samples: 4 });
  const inner = new THREE.Scene();
  inner.background = new THREE.Color(0x223344);
  for (let i = 0; i < 8; i++) {
    const m = new THREE.Mesh(
      new THREE.BoxGeometry(0.2, 2.4, 0.2),
      new THREE.MeshBasicMaterial({ color: new THREE.Color().setHSL(i / 8, 0.8, 0.6) }),
    );
    m.rotation.z = (i / 8) * Math.PI;
    inner.add(m);
  }
  const innerCam = camera(width, height, [0, 0, 4]);
  const screen = new THREE.Scene();
  const quad = new THREE.Mesh(
    new THREE.PlaneGeometry(2, 2),
    new THREE.MeshBasicMaterial({ map: target.texture }),
  );
  screen.add(quad);
  const ortho = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
  return {
    render() {
      renderer.setRenderTarget(target);
      renderer.render(inner, innerCam);
      renderer.setRenderTarget(null);
      renderer.render(screen, ortho);
    },
  };
}
