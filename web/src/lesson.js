// The interactive lesson page (`shadowlab lesson --interactive`, app/interactive_lesson.cpp): the
// step buttons show one step's section at a time; each of its views is a 3D scene to orbit, drawn
// from what the view drew in ShadowLab (views/view_export.hpp: shapes in the view's space, their
// colours, widths and lighting, the labels, the camera). Nothing is computed here but the drawing.
// With ?selftest in the address, the page clicks every step button and writes what each canvas drew
// into <pre id="selftest"> (tests/interactive_lesson_test.py).
import { recordErrors } from './errors.js';
import { OrbitView } from './orbit_view.js';
import { runSelfTest } from './self_test.js';

const errors = recordErrors();

// One canvas per view slot of a step, reused from step to step: browsers keep few WebGL contexts.
const views = [];
function viewAt(slot) {
  while (views.length <= slot) views.push(new OrbitView());
  return views[slot];
}

// The exported views, each array stored once on the page put back where it is used.
const { arrays, views: scenes } = JSON.parse(document.getElementById('lesson-scenes').textContent);
for (const shape of scenes.flatMap((scene) => scene.shapes))
  for (const [key, value] of Object.entries(shape)) if (value?.pooled !== undefined) shape[key] = arrays[value.pooled];
const buttons = Array.from(document.querySelectorAll('#steps button'));
const sections = Array.from(document.querySelectorAll('section.step'));
let shown = [];

// Shows step `index`: its button marked, its section alone shown, its canvases holding its views.
function showStep(index) {
  buttons.forEach((button, i) => button.classList.toggle('active', i === index));
  sections.forEach((section, i) => (section.hidden = i !== index));
  const orbits = Array.from(sections[index].querySelectorAll('.orbit'));
  orbits.forEach((element, slot) => viewAt(slot).show(element, scenes[Number(element.dataset.scene)]));
  shown = views.slice(0, orbits.length);
}

buttons.forEach((button, index) => button.addEventListener('click', () => showStep(index)));
// The step the address names (index.html#warp), else the first.
const named = buttons.findIndex((button) => `#${button.dataset.step}` === window.location.hash);
try {
  if (buttons.length > 0) showStep(Math.max(named, 0));
} catch (error) {
  errors.push(String(error));
}

if (new URLSearchParams(window.location.search).has('selftest'))
  runSelfTest(buttons, sections, () => shown, errors, document.getElementById('selftest'));
