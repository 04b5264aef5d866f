// The shadowgen viewer page: the shadowed scene that `shadowgen view` wrote into model.js
// (a binary glTF in base64 and what the page says about it, shadowgen/viewer/viewer_model.h)
// shown in 3D with three.js. Bundled with three.js into one classic script (viewer.js in
// the page's folder), so that the page opens from the file system: Chromium loads neither
// ES modules nor fetch() from file:// URLs, but it runs classic scripts.
//
// Colours are flat (unlit materials), so that every pixel of a piece has its legend's
// colour; the faces' outlines give the shapes. The URL's hash may say
//   #camera=top     an orthographic camera looking down the scene's -z, +y up the screen,
//                   the whole scene in view (what the page's test reads pixels from)
//   #panels=off     no legend, north arrow or hover box
// and window.shadowgenViewer offers tests the page's state (ready, project, groups).

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const model = window.shadowgenModel;
const meta = model.meta;
const hash = new URLSearchParams(window.location.hash.slice(1));
const topCamera = hash.get('camera') === 'top';
if (hash.get('panels') === 'off') document.body.classList.add('bare');

// Scene coordinates (+z up) to glTF's and three.js's (+y up): (x, y, z) -> (x, z, -y),
// relative to the model's origin, so that large coordinates keep their precision.
function toWorld(p) {
  return new THREE.Vector3(p[0] - meta.origin[0], p[2] - meta.origin[2], -(p[1] - meta.origin[1]));
}

function srgb(rgb) {
  return new THREE.Color().setRGB(rgb[0], rgb[1], rgb[2], THREE.SRGBColorSpace);
}

// The colour of a light set once some lights are switched off: the colour rule of
// shadowgen/output/obj_export.h for the lights of the set still on, over all the lights,
// so a piece darkens as its lights go out and the shadow stays grey.
const kAmbientGrey = 0.2;
function lightSetColour(lights, on) {
  const total = [0, 0, 0];
  const inSet = [0, 0, 0];
  meta.lights.forEach((light, l) => {
    for (let c = 0; c < 3; ++c) total[c] += Math.max(light.intensity[c], 0);
  });
  for (const l of lights) {
    if (!on[l]) continue;
    for (let c = 0; c < 3; ++c) inSet[c] += Math.max(meta.lights[l].intensity[c], 0);
  }
  return [0, 1, 2].map((c) => {
    const v = total[c] > 0 ? kAmbientGrey + (1 - kAmbientGrey) * (inSet[c] / total[c]) : kAmbientGrey;
    return Math.min(Math.max(v, 0), 1);
  });
}

const container = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(container.clientWidth, container.clientHeight);
renderer.setClearColor(0xf4f4f2);
container.appendChild(renderer.domElement);

const scene = new THREE.Scene();
const groupMeshes = [];  // by meta.groups index
let outlines = null;
const lightOn = (meta.lights || []).map(() => true);
const groupShown = meta.groups.map(() => true);

function decodeBase64(text) {
  const bytes = atob(text);
  const out = new Uint8Array(bytes.length);
  for (let i = 0; i < bytes.length; ++i) out[i] = bytes.charCodeAt(i);
  return out.buffer;
}

function recolour() {
  meta.groups.forEach((group, g) => {
    const mesh = groupMeshes[g];
    if (!mesh) return;
    const colour = group.lights ? lightSetColour(group.lights, lightOn) : group.colour;
    mesh.material.color.copy(srgb(colour));
    mesh.visible = groupShown[g];
  });
  render();
}

// The camera: top-down orthographic on request, else the scene's first view, else from
// the south-east above, the whole scene in view.
const box = new THREE.Box3();
let camera;
let controls;

function fitCameras() {
  const size = box.getSize(new THREE.Vector3());
  const centre = box.getCenter(new THREE.Vector3());
  const aspect = container.clientWidth / container.clientHeight;
  if (topCamera) {
    // Looking down the scene's -z (three.js's -y), the scene's +y (three.js's -z) up.
    const halfWidth = Math.max(size.x / 2, (size.z / 2) * aspect) * 1.05;
    const halfHeight = halfWidth / aspect;
    camera = new THREE.OrthographicCamera(-halfWidth, halfWidth, halfHeight, -halfHeight,
                                          0.01 * Math.max(size.y, 1), 10 * Math.max(size.y, 1) + 10);
    camera.up.set(0, 0, -1);
    camera.position.set(centre.x, box.max.y + Math.max(size.y, 1) * 2 + 1, centre.z);
    camera.lookAt(centre.x, centre.y, centre.z);
    camera.near = 0.5;
    camera.far = camera.position.y - box.min.y + 1;
    camera.updateProjectionMatrix();
    controls = new OrbitControls(camera, renderer.domElement);
    controls.target.set(centre.x, centre.y, centre.z);
    controls.enableRotate = false;
  } else {
    const radius = Math.max(size.length() / 2, 1e-9);
    camera = new THREE.PerspectiveCamera(45, aspect, radius / 1000, radius * 100);
    const view = (meta.views || []).find((v) => v.id === 'main') || (meta.views || [])[0];
    let target = centre;
    if (view) {
      camera.fov = view.fov_deg;
      camera.position.copy(toWorld(view.eye));
      target = toWorld(view.target);
      const up = view.up;
      camera.up.set(up[0], up[2], -up[1]);
    } else {
      const direction = new THREE.Vector3(1, 0.8, 1).normalize();
      const distance = radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
      camera.position.copy(centre).addScaledVector(direction, distance);
    }
    camera.updateProjectionMatrix();
    camera.lookAt(target);
    controls = new OrbitControls(camera, renderer.domElement);
    controls.target.copy(target);
  }
  controls.addEventListener('change', render);
  controls.update();
}

// The north arrow: where true north points on the screen, from the site's north axis (the
// angle from true north to the scene's +y, clockwise seen from above).
const northNeedle = document.getElementById('north-needle');
let northAngle = 0;  // degrees, clockwise from the screen's up
function updateNorth() {
  const a = THREE.MathUtils.degToRad(meta.north_axis_deg || 0);
  const north = [-Math.sin(a), Math.cos(a)];
  const from = controls.target.clone();
  const to = from.clone().add(new THREE.Vector3(north[0], 0, -north[1]));
  const p = from.project(camera);
  const q = to.project(camera);
  const dx = (q.x - p.x) * container.clientWidth;
  const dy = -(q.y - p.y) * container.clientHeight;
  const angle = THREE.MathUtils.radToDeg(Math.atan2(dx, -dy));
  northNeedle.setAttribute('transform', `rotate(${angle.toFixed(2)})`);
  northAngle = angle;
}

function render() {
  if (!camera) return;
  renderer.render(scene, camera);
  updateNorth();
}

// A legend line: a box, checked, that calls `change` with its state and redraws; `data`
// names it for tests (data-group, data-light).
function toggle(data, before, text, change) {
  const label = document.createElement('label');
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = true;
  Object.assign(box.dataset, data);
  box.addEventListener('change', () => {
    change(box.checked);
    recolour();
  });
  label.append(box, ...before, document.createTextNode(text));
  return label;
}

// Without a site, north is not known: the arrow shows the scene's +y and says so.
function labelNorth() {
  if (meta.north_axis_deg !== undefined) return;
  document.getElementById('north-label').textContent = '+y';
  document.getElementById('north').title = 'The scene has no site: the arrow shows its +y';
}

function buildLegend() {
  const legend = document.getElementById('legend');
  const title = document.createElement('h2');
  title.textContent = meta.title;
  legend.appendChild(title);
  for (const line of meta.caption) {
    const caption = document.createElement('div');
    caption.className = 'caption';
    caption.textContent = line;
    legend.appendChild(caption);
  }
  const swatches = [];
  meta.groups.forEach((group, g) => {
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = '#' + srgb(group.colour).getHexString(THREE.SRGBColorSpace);
    swatches.push(swatch);
    legend.appendChild(toggle({ group: group.name }, [swatch], group.label, (on) => {
      groupShown[g] = on;
    }));
  });
  if (meta.lights && meta.lights.length > 0) {
    const heading = document.createElement('h3');
    heading.textContent = 'Lights';
    legend.appendChild(heading);
    meta.lights.forEach((light, l) => {
      legend.appendChild(toggle({ light: light.id }, [], light.id, (on) => {
        lightOn[l] = on;
        meta.groups.forEach((group, g) => {
          swatches[g].style.background =
            '#' + srgb(lightSetColour(group.lights, lightOn)).getHexString(THREE.SRGBColorSpace);
        });
      }));
    });
  }
}

// The face under the pointer: its id, area and lit area per light (or mean sun hours).
const info = document.getElementById('info');
const raycaster = new THREE.Raycaster();
// Four significant digits, or one decimal from 100 on; no trailing zeros.
function number(x) {
  return String(Number(Math.abs(x) >= 100 ? x.toFixed(1) : x.toPrecision(4)));
}
function describe(g, faceIndex) {
  const face = meta.faces[faceIndex];
  const lines = [`face ${face.id}`, `area ${number(face.area)} m²`];
  if (face.lit) {
    meta.lights.forEach((light, l) => {
      const share = face.area > 0 ? (100 * face.lit[l]) / face.area : 0;
      lines.push(`lit by ${light.id}: ${number(face.lit[l])} m² (${share.toFixed(1)} %)`);
    });
  } else {
    lines.push(`mean sun hours ${number(face.hours)} h`);
  }
  lines.push(`here: ${meta.groups[g].label}`);
  return lines;
}
renderer.domElement.addEventListener('pointermove', (event) => {
  if (!camera) return;
  const rect = renderer.domElement.getBoundingClientRect();
  const pointer = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
                                    -((event.clientY - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(pointer, camera);
  const hits = raycaster.intersectObjects(groupMeshes.filter((m) => m && m.visible), false);
  info.replaceChildren();
  if (hits.length === 0) return;
  const hit = hits[0];
  const faceIndex = hit.object.geometry.getAttribute('_face').getX(hit.face.a);
  for (const line of describe(hit.object.userData.group, faceIndex)) {
    const div = document.createElement('div');
    div.textContent = line;
    info.appendChild(div);
  }
});

window.addEventListener('resize', () => {
  const aspect = container.clientWidth / container.clientHeight;
  renderer.setSize(container.clientWidth, container.clientHeight);
  if (camera.isPerspectiveCamera) {
    camera.aspect = aspect;
  } else {
    const halfHeight = (camera.right - camera.left) / 2 / aspect;
    camera.top = halfHeight;
    camera.bottom = -halfHeight;
  }
  camera.updateProjectionMatrix();
  render();
});

// For tests: whether the page is drawn, where a point of the scene lands on the screen (CSS
// pixels from the page's top left), the colour each group shows (sRGB bytes), and where the
// north arrow points (degrees clockwise from the screen's up).
window.shadowgenViewer = {
  ready: false,
  project(x, y, z) {
    const p = toWorld([x, y, z]).project(camera);
    return { x: ((p.x + 1) / 2) * container.clientWidth, y: ((1 - p.y) / 2) * container.clientHeight };
  },
  north() {
    return northAngle;
  },
  groups() {
    return meta.groups.map((group, g) => ({
      name: group.name,
      colour: groupMeshes[g] ? groupMeshes[g].material.color.getHex(THREE.SRGBColorSpace) : null,
    }));
  },
};

new GLTFLoader().parse(decodeBase64(model.glb), '', (gltf) => {
  // The file's root node carries the origin as its translation; taking it off again in the
  // scene's root keeps the coordinates three.js multiplies small.
  const root = gltf.scene;
  root.position.set(-meta.origin[0], -meta.origin[2], meta.origin[1]);
  // The file's materials are the page's groups, in order (a mesh per material that has
  // pieces); the mesh of lines is the outlines.
  root.traverse((object) => {
    const association = object.isMesh ? gltf.parser.associations.get(object.material) : undefined;
    if (association && association.materials !== undefined) {
      const g = association.materials;
      const group = meta.groups[g];
      object.userData.group = g;
      object.material = new THREE.MeshBasicMaterial({ color: srgb(group.colour), side: THREE.DoubleSide });
      groupMeshes[g] = object;
    } else if (object.isLineSegments) {
      object.material = new THREE.LineBasicMaterial({ color: 0x333333 });
      outlines = object;
    }
  });
  root.updateMatrixWorld(true);
  scene.add(root);
  box.setFromObject(root);
  fitCameras();
  buildLegend();
  labelNorth();
  recolour();
  window.shadowgenViewer.ready = true;
}, (error) => {
  console.error('shadowgen viewer: the model in model.js could not be read: ' + error);
});
