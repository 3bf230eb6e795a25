// One canvas of the page, orbited with the mouse (three.js's OrbitControls): a WebGL renderer with
// layers of labels and of the view's legend over it, moved to the step's view it shows and given
// that view's scene. Each scene is built once and keeps its camera, so a view orbited stays so when
// its step comes back.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';
import { buildScene } from './scene_builder.js';

// Colours as ShadowLab gives them: no conversion to linear and back.
THREE.ColorManagement.enabled = false;

const kBackgroundTolerance = 8;  // of 255, per channel: a pixel this close to the background is background

// The view's legend as ShadowLab's views draw it: a swatch and its words per entry, in rows from the top left.
function fillLegend(element, entries) {
  element.replaceChildren(...entries.map((entry) => {
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = `rgb(${entry.colour.map((c) => Math.round(255 * c)).join(', ')})`;
    const line = document.createElement('span');
    line.append(swatch, entry.text);
    return line;
  }));
}

export class OrbitView {
  constructor() {
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
    this.labels = new CSS2DRenderer();
    this.labels.domElement.className = 'labels';
    this.legend = document.createElement('div');
    this.legend.className = 'legend';
    this.built = new Map();
    this.controls = null;
    this.current = null;
  }

  // Shows the exported view `view` in the page element `element`, at the element's size.
  show(element, view) {
    const size = { width: element.clientWidth, height: element.clientHeight };
    element.append(this.renderer.domElement, this.labels.domElement, this.legend);
    fillLegend(this.legend, view.legend);
    this.renderer.setSize(size.width, size.height);
    this.labels.setSize(size.width, size.height);
    this.labels.domElement.replaceChildren();  // the labels of the scene shown before
    if (!this.built.has(view)) this.built.set(view, buildScene(view, size));
    this.current = this.built.get(view);
    this.controls?.dispose();
    this.controls = new OrbitControls(this.current.camera, this.renderer.domElement);
    this.controls.target.copy(this.current.target);
    this.controls.addEventListener('change', () => this.render());
    this.controls.update();
    this.render();
  }

  render() {
    const { scene, camera, background } = this.current;
    this.current.fitDepthRange();
    this.renderer.setClearColor(new THREE.Color(...background));
    this.renderer.render(scene, camera);
    this.labels.render(scene, camera);
  }

  // Renders and counts the pixels that are not the background; `hash` tells two pictures apart.
  drawnPixels() {
    this.render();
    const gl = this.renderer.getContext();
    const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const background = this.current.background.map((c) => Math.round(255 * c));
    let drawn = 0, hash = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      if ([0, 1, 2].some((c) => Math.abs(pixels[i + c] - background[c]) > kBackgroundTolerance)) ++drawn;
      hash = (Math.imul(hash, 31) + pixels[i] + 7 * pixels[i + 1] + 13 * pixels[i + 2]) >>> 0;
    }
    return { drawn, pixels: width * height, hash };
  }
}
