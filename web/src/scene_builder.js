// A view exported by ShadowLab (views/view_export.hpp) as a three.js scene: its faces, lines and
// points with their colours, widths, opacity and lighting as VTK drew them (lit faces: 0.3 ambient
// and 0.7 diffuse from a headlight, VTK's; lines and points unlit), its labels beside their points,
// and its camera. The shapes are drawn as given, in the view's own space.
import * as THREE from 'three';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { CSS2DObject } from 'three/addons/renderers/CSS2DRenderer.js';

const kAmbient = 0.3, kDiffuse = 0.7;  // views/space_canvas.cpp's faces
const kLabelOffset = [6, 4];           // pixels right and up of the point, as views/space_canvas.cpp

const colourOf = (rgb) => new THREE.Color(rgb[0], rgb[1], rgb[2]);
const cssColour = (rgb) => `rgb(${rgb.map((c) => Math.round(255 * c)).join(', ')})`;

// What every kind of cell shares: its colour (white under colours per point, which replace it) and
// its opacity; translucent ones write no depth, as VTK's.
function paint(shape, colours) {
  return {
    color: colours ? 0xffffff : colourOf(shape.colour),
    vertexColors: Boolean(colours),
    transparent: shape.opacity < 1,
    opacity: shape.opacity,
    depthWrite: shape.opacity >= 1,
  };
}

function facesOf(shape) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(shape.faces, 3));
  if (shape.face_colours) geometry.setAttribute('color', new THREE.Float32BufferAttribute(shape.face_colours, 3));
  geometry.computeVertexNormals();
  // Pushed back a little, so that the lines lying on a face draw in front of it.
  const options = { ...paint(shape, shape.face_colours), side: THREE.DoubleSide, polygonOffset: true,
                    polygonOffsetFactor: 1, polygonOffsetUnits: 1 };
  return new THREE.Mesh(geometry, shape.lit ? new THREE.MeshLambertMaterial(options) : new THREE.MeshBasicMaterial(options));
}

function linesOf(shape, size) {
  const geometry = new LineSegmentsGeometry();
  geometry.setPositions(shape.lines);
  if (shape.line_colours) geometry.setColors(shape.line_colours);
  const material = new LineMaterial({ ...paint(shape, shape.line_colours), linewidth: shape.line_width });
  material.resolution.set(size.width, size.height);
  return new LineSegments2(geometry, material);
}

function pointsOf(shape) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(shape.points, 3));
  if (shape.point_colours) geometry.setAttribute('color', new THREE.Float32BufferAttribute(shape.point_colours, 3));
  const material = new THREE.PointsMaterial({ ...paint(shape, shape.point_colours), size: shape.point_size,
                                              sizeAttenuation: false });
  return new THREE.Points(geometry, material);
}

function labelOf(label) {
  const text = document.createElement('span');
  text.textContent = label.text;
  text.style.color = cssColour(label.colour);
  const box = document.createElement('div');
  box.className = 'label';
  box.style.padding = `0 0 ${kLabelOffset[1]}px ${kLabelOffset[0]}px`;
  box.append(text);
  const object = new CSS2DObject(box);
  object.position.set(...label.at);
  object.center.set(0, 1);  // the box's lower left corner at the point
  return object;
}

function cameraOf(view, aspect) {
  const c = view.camera;
  const camera = c.parallel
    ? new THREE.OrthographicCamera(-c.parallel_scale * aspect, c.parallel_scale * aspect, c.parallel_scale,
                                   -c.parallel_scale)
    : new THREE.PerspectiveCamera(c.view_angle, aspect);
  camera.position.set(...c.position);
  camera.up.set(...c.view_up);
  camera.lookAt(...c.focal_point);
  return camera;
}

// The sphere around every point drawn: the camera's near and far planes are kept around it as it orbits.
function boundsOf(view) {
  const box = new THREE.Box3();
  const point = new THREE.Vector3();
  for (const shape of view.shapes)
    for (const positions of [shape.faces, shape.lines, shape.points])
      for (let i = 0; positions && i < positions.length; i += 3) box.expandByPoint(point.fromArray(positions, i));
  for (const label of view.labels) box.expandByPoint(point.fromArray(label.at));
  return box.getBoundingSphere(new THREE.Sphere());
}

// { scene, camera, target, background, fitDepthRange() } for an exported view drawn at `size` pixels.
export function buildScene(view, size) {
  const scene = new THREE.Scene();
  for (const shape of view.shapes) {
    if (shape.faces) scene.add(facesOf(shape));
    if (shape.lines) scene.add(linesOf(shape, size));
    if (shape.points) scene.add(pointsOf(shape));
  }
  for (const label of view.labels) scene.add(labelOf(label));
  const camera = cameraOf(view, size.width / size.height);
  const headlight = new THREE.DirectionalLight(0xffffff, kDiffuse * Math.PI);  // three's Lambert divides by pi
  headlight.position.set(0, 0, 0);
  headlight.target.position.set(0, 0, -1);
  camera.add(headlight, headlight.target);
  scene.add(camera, new THREE.AmbientLight(0xffffff, kAmbient * Math.PI));
  const bounds = boundsOf(view);
  const reach = 1.05 * bounds.radius + 1e-9;
  return {
    scene,
    camera,
    target: new THREE.Vector3(...view.camera.focal_point),
    background: view.background,
    fitDepthRange() {
      const distance = camera.position.distanceTo(bounds.center);
      camera.far = distance + reach;
      camera.near = camera.isOrthographicCamera ? distance - reach : Math.max(distance - reach, 1e-4 * camera.far);
      camera.updateProjectionMatrix();
    },
  };
}
