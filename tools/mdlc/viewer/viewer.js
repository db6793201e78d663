// viewer.js - the script of the page `mdlc view` writes (tools/mdlc/view.cc).
//
// It reads the model JSON, loads three.js from the page itself, builds one
// three.js group per body, and places the bodies with the plant's own forward
// kinematics: X_WC = X_WP * X_PF * X_FM(q) * X_CM^-1 with X_FM(q) per joint
// type exactly as backend/kinematics.cc computes it, in double precision.
// The page exposes window.mdlcBodyPoses(q) (X_WB of every body) and
// window.mdlcSetPositions(q) so that tests can hold it to the plant; it opens
// in model.q0 (the default positions with mdlc view --q applied); opened
// as model.html#selftest=JSON it runs those checks and writes the results
// into the pre element "mdlc-selftest" (tests/cli/view_test.py).

const model = JSON.parse(document.getElementById('mdlc-model').textContent);

// ---- three.js from the page: base64 text -> module URLs of our own
function moduleUrl(text) {
  return URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
}
function embedded(id) {
  const bytes = Uint8Array.from(atob(document.getElementById(id).textContent), (c) => c.charCodeAt(0));
  return new TextDecoder().decode(bytes);
}
const threeUrl = moduleUrl(embedded('mdlc-three'));
const THREE = await import(threeUrl);
// OrbitControls imports 'three' by name; no import map is needed when it is
// pointed at the URL above instead
const orbitText = embedded('mdlc-orbit-controls').replace(/from\s+'three'/g, `from '${threeUrl}'`);
const { OrbitControls } = await import(moduleUrl(orbitText));

// ---- rigid transforms {R: 9 numbers row-major, p: 3 numbers} (transform.h)
const identity = () => ({ R: [1, 0, 0, 0, 1, 0, 0, 0, 1], p: [0, 0, 0] });
function mulR(A, B) {
  const C = new Array(9);
  for (let r = 0; r < 3; ++r) {
    for (let c = 0; c < 3; ++c) {
      C[3 * r + c] = A[3 * r] * B[c] + A[3 * r + 1] * B[3 + c] + A[3 * r + 2] * B[6 + c];
    }
  }
  return C;
}
function mulRv(R, v) {
  return [0, 1, 2].map((r) => R[3 * r] * v[0] + R[3 * r + 1] * v[1] + R[3 * r + 2] * v[2]);
}
function compose(X, Y) {
  const Rp = mulRv(X.R, Y.p);
  return { R: mulR(X.R, Y.R), p: [Rp[0] + X.p[0], Rp[1] + X.p[1], Rp[2] + X.p[2]] };
}
function inverse(X) {
  const R = X.R;
  const Rt = [R[0], R[3], R[6], R[1], R[4], R[7], R[2], R[5], R[8]];
  const p = mulRv(Rt, X.p);
  return { R: Rt, p: [-p[0], -p[1], -p[2]] };
}

// Eigen::AngleAxisd::toRotationMatrix, term for term
function rotationAboutAxis(a, angle) {
  const s = Math.sin(angle), c = Math.cos(angle);
  const sa = [s * a[0], s * a[1], s * a[2]], ca = [(1 - c) * a[0], (1 - c) * a[1], (1 - c) * a[2]];
  const R = new Array(9);
  let t = ca[0] * a[1];
  R[1] = t - sa[2]; R[3] = t + sa[2];
  t = ca[0] * a[2];
  R[2] = t + sa[1]; R[6] = t - sa[1];
  t = ca[1] * a[2];
  R[5] = t - sa[0]; R[7] = t + sa[0];
  R[0] = ca[0] * a[0] + c; R[4] = ca[1] * a[1] + c; R[8] = ca[2] * a[2] + c;
  return R;
}
const Rx = (angle) => rotationAboutAxis([1, 0, 0], angle);
const Ry = (angle) => rotationAboutAxis([0, 1, 0], angle);
const Rz = (angle) => rotationAboutAxis([0, 0, 1], angle);
// fixed-axis roll-pitch-yaw: Rz(yaw) * Ry(pitch) * Rx(roll)
const rotationFromRpy = (r, p, y) => mulR(Rz(y), mulR(Ry(p), Rx(r)));
function quaternionRotation(w, x, y, z) {
  const n = Math.hypot(w, x, y, z);
  if (n === 0) return identity().R;
  w /= n; x /= n; y /= n; z /= n;
  return [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
          2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)];
}

// the roll, pitch, yaw (fixed axes, as rotationFromRpy) of a rotation; pitch
// in [-pi/2, pi/2]
function rpyOfRotation(R) {
  return [Math.atan2(R[7], R[8]), Math.asin(Math.max(-1, Math.min(1, -R[6]))), Math.atan2(R[3], R[0])];
}
// the unit quaternion [w, x, y, z] of rotationFromRpy(roll, pitch, yaw)
function quaternionOfRpy(roll, pitch, yaw) {
  const cr = Math.cos(roll / 2), sr = Math.sin(roll / 2), cp = Math.cos(pitch / 2);
  const sp = Math.sin(pitch / 2), cy = Math.cos(yaw / 2), sy = Math.sin(yaw / 2);
  return [cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
          cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy];
}

// X_FM(q) per joint type (backend/kinematics.cc JointPose)
function jointPose(joint, q) {
  const a = joint.axis;
  switch (joint.type) {
    case 'revolute': return { R: rotationAboutAxis(a, q[0]), p: [0, 0, 0] };
    case 'prismatic': return { R: identity().R, p: [a[0] * q[0], a[1] * q[0], a[2] * q[0]] };
    case 'screw': {
      const d = q[0] * (joint.pitch / (2 * Math.PI));
      return { R: rotationAboutAxis(a, q[0]), p: [a[0] * d, a[1] * d, a[2] * d] };
    }
    case 'universal': return { R: mulR(Rx(q[0]), Ry(q[1])), p: [0, 0, 0] };
    case 'ball': return { R: rotationFromRpy(q[0], q[1], q[2]), p: [0, 0, 0] };
    case 'planar': return { R: Rz(q[2]), p: [q[0], q[1], 0] };
    case 'curvilinear': return joint.X_FM;  // shown at rest (see the page's notes)
    case 'quaternion_floating':
      return { R: quaternionRotation(q[0], q[1], q[2], q[3]), p: [q[4], q[5], q[6]] };
    case 'rpy_floating': return { R: rotationFromRpy(q[0], q[1], q[2]), p: [q[3], q[4], q[5]] };
    default: return identity();  // weld
  }
}

// backend/kinematics.cc BodyPosesInWorld: parents come first in joint_order
const X_CMinv = model.joints.map((j) => inverse(j.X_CM));
function bodyPoses(q) {
  if (q.length !== model.num_positions) {
    throw new Error(`q has ${q.length} entries; the plant has ${model.num_positions} positions`);
  }
  const X_WB = model.bodies.map(identity);
  for (const id of model.joint_order) {
    const joint = model.joints[id];
    const X_FM = jointPose(joint, q.slice(joint.q_start, joint.q_start + joint.nq));
    X_WB[joint.child] = compose(compose(compose(X_WB[joint.parent], joint.X_PF), X_FM), X_CMinv[id]);
  }
  return X_WB;
}

function defaultPositions() {
  const q = new Array(model.num_positions).fill(0);
  for (const joint of model.joints) {
    for (let k = 0; k < joint.nq; ++k) q[joint.q_start + k] = joint.default[k] ?? 0;
  }
  return q;
}

// ---- the scene: world Z up, as the plant's
const view = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xeef1f5);
const camera = new THREE.PerspectiveCamera(45, 1, 0.001, 1000);
camera.up.set(0, 0, 1);
const controls = new OrbitControls(camera, renderer.domElement);
scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.set(3, 2, 5);
scene.add(sun);

function matrixOf(X) {
  const R = X.R, p = X.p;
  return new THREE.Matrix4().set(R[0], R[1], R[2], p[0], R[3], R[4], R[5], p[1],
                                 R[6], R[7], R[8], p[2], 0, 0, 0, 1);
}
function base64Array(text, Type) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  return new Type(bytes.buffer);
}
const meshGeometries = model.meshes.map((m) => {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position',
                        new THREE.BufferAttribute(base64Array(m.vertices, Float32Array), 3));
  const triangles = base64Array(m.triangles, Uint32Array);
  geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
  geometry.computeVertexNormals();
  // the file's colour runs [first triangle, r, g, b, a] as draw groups, one
  // material each (used where the geometry is drawn in the file's colours)
  const runs = m.colors ?? [];
  runs.forEach((run, i) => {
    const end = i + 1 < runs.length ? runs[i + 1][0] : triangles.length / 3;
    geometry.addGroup(3 * run[0], 3 * (end - run[0]), i);
  });
  return geometry;
});
function material(rgba, doubleSided) {
  return new THREE.MeshStandardMaterial({
    color: new THREE.Color().setRGB(rgba[0], rgba[1], rgba[2], THREE.SRGBColorSpace),
    opacity: rgba[3], transparent: rgba[3] < 1, roughness: 0.7, metalness: 0.05,
    side: doubleSided ? THREE.DoubleSide : THREE.FrontSide,
  });
}
const materialsOf = (object) => (Array.isArray(object.material) ? object.material : [object.material]);

// Drake's shapes in their frame G: cylinders and capsules along z, box by
// full size, ellipsoid by semi-axes, half space the z <= 0 side of z = 0
function shapeObject(shape) {
  switch (shape.type) {
    case 'box': return [new THREE.BoxGeometry(...shape.size), null];
    case 'sphere': return [new THREE.SphereGeometry(shape.radius, 32, 16), null];
    case 'cylinder': return [new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 32),
                             new THREE.Matrix4().makeRotationX(Math.PI / 2)];
    case 'capsule': return [new THREE.CapsuleGeometry(shape.radius, shape.length, 8, 24),
                            new THREE.Matrix4().makeRotationX(Math.PI / 2)];
    case 'ellipsoid': return [new THREE.SphereGeometry(1, 32, 16),
                              new THREE.Matrix4().makeScale(shape.a, shape.b, shape.c)];
    case 'half_space': return [new THREE.PlaneGeometry(1, 1), null];  // sized to the model below
    case 'mesh': case 'convex':
      if (shape.mesh < 0) return [null, null];
      return [meshGeometries[shape.mesh], new THREE.Matrix4().makeScale(...shape.scale)];
    default: return [null, null];
  }
}

const bodyGroups = model.bodies.map((body, index) => {
  const group = new THREE.Group();
  group.name = body.scoped_name;
  group.matrixAutoUpdate = false;
  group.userData.body = index;
  scene.add(group);
  return group;
});
const byRole = { illustration: [], proximity: [], perception: [], frames: [] };
for (const g of model.geometries) {
  const [geometry, shapeMatrix] = shapeObject(g.shape);
  if (!geometry) continue;
  const proximityOnly = !g.roles.includes('illustration') && g.roles.includes('proximity');
  const rgba = g.rgba ?? (proximityOnly ? [0.95, 0.55, 0.15, 0.45] : [0.7, 0.7, 0.72, 1]);
  const doubleSided = g.shape.type === 'half_space' || Boolean(geometry.index);
  // a mesh file's own colours win over the model's, as in Drake and RViz;
  // collision geometry keeps its one colour, to tell it apart
  const runs = g.shape.mesh >= 0 ? model.meshes[g.shape.mesh].colors ?? [] : [];
  const object = new THREE.Mesh(geometry, runs.length && !proximityOnly
    ? runs.map((run) => material(run.slice(1), doubleSided)) : material(rgba, doubleSided));
  object.matrixAutoUpdate = false;
  object.matrix.copy(matrixOf(g.X_BG));
  if (shapeMatrix) object.matrix.multiply(shapeMatrix);
  object.userData.body = g.body;
  object.userData.halfSpace = g.shape.type === 'half_space';
  object.name = g.name;
  bodyGroups[g.body].add(object);
  for (const role of g.roles) byRole[role]?.push(object);
}

// frames as triads sized to the model
const bounds = new THREE.Box3();
function fitBounds() {
  scene.updateMatrixWorld(true);
  bounds.makeEmpty();
  // a half space is drawn as a finite floor; it says nothing of the model's size
  for (const group of bodyGroups) {
    for (const object of group.children) if (!object.userData.halfSpace) bounds.expandByObject(object);
  }
  if (bounds.isEmpty()) bounds.set(new THREE.Vector3(-0.5, -0.5, -0.5), new THREE.Vector3(0.5, 0.5, 0.5));
}

// names without their model instance when the page shows only one
const instances = new Set(model.bodies.filter((b) => b.parent >= 0).map((b) => b.model));
const label = (entity) => (instances.size === 1 ? entity.name : entity.scoped_name);

// ---- positions, sliders and the poses shown
let q = (model.q0 ?? defaultPositions()).slice();
function show() {
  const X_WB = bodyPoses(q);
  X_WB.forEach((X, b) => bodyGroups[b].matrix.copy(matrixOf(X)));
  scene.updateMatrixWorld(true);
}
show();
fitBounds();
const size = bounds.getSize(new THREE.Vector3()).length() || 1;
for (const group of bodyGroups) {
  for (const object of group.children) {
    if (object.userData.halfSpace) object.matrix.multiply(new THREE.Matrix4().makeScale(size, size, 1));
  }
}
// each body's own frame, then the model's named frames
const triads = model.bodies.map((body, index) => ({ name: body.scoped_name, body: index,
                                                     X_BF: identity() }));
for (const frame of [...triads, ...model.frames]) {
  const axes = new THREE.AxesHelper(size * 0.06);
  axes.matrixAutoUpdate = false;
  axes.matrix.copy(matrixOf(frame.X_BF));
  axes.name = frame.name;
  bodyGroups[frame.body].add(axes);
  byRole.frames.push(axes);
}
const center = bounds.getCenter(new THREE.Vector3());
camera.position.copy(center).add(new THREE.Vector3(1.1, -1.3, 0.8).multiplyScalar(size));
camera.near = size / 1000;
camera.far = size * 100;
controls.target.copy(center);
controls.update();

// ---- sliders: one per coordinate a person moves. Each maps to q entries
// one to one, except a quaternion floating joint's: it gets x, y, z, roll,
// pitch, yaw (a quaternion's components are no coordinates to drag), the
// angles held by the page and turned into q's quaternion
const sliders = [];
const sliderBox = document.getElementById('sliders');
const coordinateNames = {
  universal: ['x', 'y'], ball: ['roll', 'pitch', 'yaw'], planar: ['x', 'y', 'theta'],
  rpy_floating: ['roll', 'pitch', 'yaw', 'x', 'y', 'z'],
};
const floatingRpy = new Map();  // quaternion floating joint id -> [roll, pitch, yaw]
function syncFloatingRpy() {
  model.joints.forEach((joint, id) => {
    if (joint.type !== 'quaternion_floating') return;
    const s = joint.q_start;
    floatingRpy.set(id, rpyOfRotation(quaternionRotation(q[s], q[s + 1], q[s + 2], q[s + 3])));
  });
}
// a joint's coordinates: name, read(), write(value), offset (its q entry
// within the joint's, which also indexes the joint's limits; null for a
// quaternion's angles) and whether it is a length
function coordinatesOf(joint, id) {
  const s = joint.q_start;
  const entry = (k, name, translational) => ({
    name, translational, offset: k,
    read: () => q[s + k], write: (value) => { q[s + k] = value; },
  });
  if (joint.type === 'quaternion_floating') {
    const angle = (k, name) => ({
      name, translational: false, offset: null,
      read: () => floatingRpy.get(id)[k],
      write: (value) => {
        const rpy = floatingRpy.get(id);
        rpy[k] = value;
        quaternionOfRpy(...rpy).forEach((x, i) => { q[s + i] = x; });
      },
    });
    return [entry(4, 'x', true), entry(5, 'y', true), entry(6, 'z', true),
            angle(0, 'roll'), angle(1, 'pitch'), angle(2, 'yaw')];
  }
  const names = coordinateNames[joint.type] ?? [];
  const all = Array.from({ length: joint.nq }, (_, k) => entry(k, names[k],
    joint.type === 'prismatic' || (joint.type === 'planar' && k < 2) ||
    (joint.type === 'rpy_floating' && k >= 3)));
  // translation first, as for the quaternion floating joint
  return joint.type === 'rpy_floating' ? [...all.slice(3), ...all.slice(0, 3)] : all;
}
// a coordinate's slider range: its joint's limits where finite (the slider
// holds q to them), else a span that fits the model and widens to any value
function rangeOf(joint, c) {
  // limits are per velocity; they match the positions wherever nq == nv
  const limited = c.offset !== null && joint.nq === joint.lower.length;
  const lo = limited ? joint.lower[c.offset] : null, hi = limited ? joint.upper[c.offset] : null;
  const span = c.translational ? Math.max(1, size) : Math.PI;
  const loFixed = lo !== null && Number.isFinite(lo), hiFixed = hi !== null && Number.isFinite(hi);
  return { lo: loFixed ? lo : -span, hi: hiFixed ? hi : span, loFixed, hiFixed };
}
// puts q into the sliders: a value past a limit is clamped there, in q too,
// so that the label, the slider and the bodies shown say the same
function syncSliders() {
  syncFloatingRpy();
  for (const slider of sliders) {
    const { input, value, coordinate, range } = slider;
    const wanted = coordinate.read();
    if (!range.loFixed && wanted < Number(input.min)) input.min = wanted;
    if (!range.hiFixed && wanted > Number(input.max)) input.max = wanted;
    // clamped here, not by the input: its value reads back rounded
    const held = Math.min(Math.max(wanted, Number(input.min)), Number(input.max));
    input.value = held;
    if (held !== wanted) coordinate.write(held);
    value.textContent = held.toFixed(3);
    value.classList.toggle('clamped', held !== wanted);
    value.title = held !== wanted ? `${wanted} is past the joint's limit: shown at ${held}` : '';
  }
}
syncFloatingRpy();
for (const id of model.joint_order) {
  const joint = model.joints[id];
  for (const coordinate of coordinatesOf(joint, id)) {
    const range = rangeOf(joint, coordinate);
    const row = document.createElement('label');
    row.className = 'slider';
    const name = document.createElement('span');
    name.textContent = label(joint) + (coordinate.name ? `.${coordinate.name}` : '');
    const where = coordinate.offset === null ? 'its quaternion' : `q[${joint.q_start + coordinate.offset}]`;
    name.title = `${joint.scoped_name}: ${joint.type} joint, ${where}` + (joint.source ? `, ${joint.source}` : '') +
                 (joint.type === 'curvilinear' ? ' (shown at rest)' : '');
    const input = document.createElement('input');
    input.type = 'range';
    input.min = range.lo; input.max = range.hi;
    input.step = 'any';  // a step would round q to its grid
    input.dataset.joint = joint.scoped_name;
    input.dataset.coordinate = coordinate.name ?? '';
    const value = document.createElement('span');
    input.addEventListener('input', () => {
      coordinate.write(Number(input.value));
      value.textContent = Number(input.value).toFixed(3);
      value.classList.remove('clamped');
      value.title = '';
      show();
      showSelection();
    });
    row.append(name, input, value);
    sliderBox.append(row);
    sliders.push({ input, value, coordinate, range });
  }
}
syncSliders();
show();
if (sliders.length === 0) sliderBox.textContent = 'no joint moves';

// role toggles: illustration shown unless there is none, then proximity
const toggles = document.getElementById('toggles');
const hasIllustration = byRole.illustration.length > 0;
for (const [role, shown] of [['illustration', hasIllustration], ['proximity', !hasIllustration],
                             ['perception', false], ['frames', true]]) {
  if (byRole[role].length === 0) continue;
  const row = document.createElement('label');
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = shown;
  box.dataset.role = role;
  const apply = () => {
    // a geometry shows when any role it has is switched on
    for (const object of byRole[role]) object.visible = false;
    for (const [other, objects] of Object.entries(byRole)) {
      const on = toggles.querySelector(`input[data-role="${other}"]`)?.checked;
      if (on) for (const object of objects) object.visible = true;
    }
  };
  box.addEventListener('change', apply);
  row.append(box, ` ${role} (${byRole[role].length}) `);
  toggles.append(row);
}
for (const objects of Object.values(byRole)) for (const o of objects) o.visible = false;
for (const box of toggles.querySelectorAll('input')) box.dispatchEvent(new Event('change'));

// notes: what the page cannot show
const notes = document.getElementById('notes');
for (const note of model.notes) {
  const p = document.createElement('p');
  p.className = 'note';
  p.textContent = note;
  notes.append(p);
}

// ---- the kinematic tree and the selected body's mass properties
const treeItems = new Map();
let selected = -1;
function buildTree(index) {
  const body = model.bodies[index];
  const li = document.createElement('li');
  const item = document.createElement('span');
  item.className = 'body';
  item.textContent = index === 0 ? 'world' : label(body);
  item.title = body.scoped_name;
  item.addEventListener('click', () => select(index));
  li.append(item);
  if (body.joint >= 0) {
    const joint = model.joints[body.joint];
    const j = document.createElement('span');
    j.className = 'joint';
    j.textContent = ` \u2190 ${label(joint)} (${joint.type})`;
    li.append(j);
  }
  treeItems.set(index, item);
  const children = model.bodies.map((b, i) => [b, i]).filter(([b]) => b.parent === index);
  if (children.length) {
    const ul = document.createElement('ul');
    for (const [, i] of children) ul.append(buildTree(i));
    li.append(ul);
  }
  return li;
}
const treeRoot = document.createElement('ul');
treeRoot.style.paddingLeft = '0';
treeRoot.append(buildTree(0));
document.getElementById('tree').append(treeRoot);

const fmtNum = (x) => (Math.abs(x) < 1e-12 ? '0' : Number(x.toPrecision(6)).toString());
const fmtVec = (v) => `[${v.map(fmtNum).join(', ')}]`;
function showSelection() {
  const info = document.getElementById('info');
  if (selected < 0) return;
  const body = model.bodies[selected];
  const I = body.inertia;
  const X = bodyPoses(q)[selected];
  info.textContent = [
    body.scoped_name,
    `mass    ${fmtNum(body.mass)} kg`,
    `com     ${fmtVec(body.com)} m, in B`,
    `I_Bcm   Ixx Iyy Izz ${fmtVec([I[0], I[4], I[8]])}`,
    `(kg m2) Ixy Ixz Iyz ${fmtVec([I[1], I[2], I[5]])}`,
    `p_WB    ${fmtVec(X.p)} m`,
    body.joint >= 0 ? `joint   ${model.joints[body.joint].scoped_name} (${model.joints[body.joint].type})` : 'the world',
    `source  ${body.source || 'none'}`,
  ].join('\n');
}
function select(index) {
  if (treeItems.has(selected)) treeItems.get(selected).classList.remove('selected');
  selected = index;
  treeItems.get(index)?.classList.add('selected');
  for (const group of bodyGroups) {
      group.traverse((o) => { if (o.isMesh) for (const m of materialsOf(o)) m.emissive?.setHex(0); });
  }
  bodyGroups[index].traverse((o) => {
    if (o.isMesh) for (const m of materialsOf(o)) m.emissive?.setHex(0x553300);
  });
  showSelection();
}
const raycaster = new THREE.Raycaster();
let pressed = null;
renderer.domElement.addEventListener('pointerdown', (e) => { pressed = [e.clientX, e.clientY]; });
renderer.domElement.addEventListener('pointerup', (e) => {
  // a click, not the end of an orbit
  if (!pressed || Math.hypot(e.clientX - pressed[0], e.clientY - pressed[1]) > 4) return;
  const rect = renderer.domElement.getBoundingClientRect();
  const pointer = new THREE.Vector2(((e.clientX - rect.left) / rect.width) * 2 - 1,
                                    -((e.clientY - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(pointer, camera);
  const hit = raycaster.intersectObjects(bodyGroups, true).find((h) => h.object.visible &&
                                                                      h.object.isMesh);
  if (hit) select(hit.object.userData.body);
});

// page.html#select=BODY opens with that body (scoped or local name) selected
const preselect = /^#select=(.*)$/.exec(window.location.hash);
if (preselect) {
  const name = decodeURIComponent(preselect[1]);
  const index = model.bodies.findIndex((b) => b.scoped_name === name || b.name === name);
  if (index >= 0) select(index);
}

// ---- rendering
function resize() {
  const w = view.clientWidth || 800, h = view.clientHeight || 600;
  renderer.setSize(w, h);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();
function frame() {
  controls.update();
  renderer.render(scene, camera);
  requestAnimationFrame(frame);
}
renderer.render(scene, camera);
requestAnimationFrame(frame);

// ---- for tests
window.mdlcModel = model;
window.mdlcBodyPoses = (positions) => bodyPoses(positions);
window.mdlcSetPositions = (positions) => {
  q = positions.slice();
  syncSliders();
  show();
};
// the poses the scene shows, from three.js' own matrices
window.mdlcShownPoses = () => bodyGroups.map((group) => {
  const e = group.matrixWorld.elements;  // column-major
  return { R: [e[0], e[4], e[8], e[1], e[5], e[9], e[2], e[6], e[10]], p: [e[12], e[13], e[14]] };
});

// #selftest={"qs": [[...], ...], "slider": JOINT, "value": x, "drag":
// [[JOINT, COORDINATE, x], ...], "select": BODY}: poses at each q; the
// configuration shown on opening (q, poses, each slider's value and label);
// the shown poses before and after moving one slider with a real input
// event; q and the shown poses after dragging the sliders named; where the
// selected body's panel lies in the window. Written into the page for a
// headless browser to dump.
const sliderState = () => sliders.map(({ input, value }) => ({
  joint: input.dataset.joint, coordinate: input.dataset.coordinate, value: Number(input.value),
  label: value.textContent, clamped: value.classList.contains('clamped'),
  min: Number(input.min), max: Number(input.max),
}));
const selftest = /^#selftest=(.*)$/.exec(window.location.hash);
if (selftest) {
  const request = JSON.parse(decodeURIComponent(selftest[1]));
  const report = { poses: request.qs.map((positions) => bodyPoses(positions)) };
  const opened = q.slice();
  report.opened = { q: opened, shown: window.mdlcShownPoses(), sliders: sliderState() };
  if (request.drag !== undefined) {
    for (const [joint, coordinate, x] of request.drag) {
      // the joint by scoped name or its own
      const named = (s) => s.input.dataset.joint === joint || s.input.dataset.joint.endsWith(`::${joint}`);
      const input = sliders.find((s) => named(s) && s.input.dataset.coordinate === coordinate)?.input;
      if (!input) throw new Error(`no slider ${joint}.${coordinate}`);
      input.value = x;
      input.dispatchEvent(new Event('input'));
    }
    report.dragged = { q: q.slice(), shown: window.mdlcShownPoses(), sliders: sliderState() };
    window.mdlcSetPositions(opened);
  }
  if (request.select !== undefined) {
    select(model.bodies.findIndex((b) => b.scoped_name === request.select || b.name === request.select));
    const box = document.getElementById('selection').getBoundingClientRect();
    report.selection = { left: box.left, top: box.top, right: box.right, bottom: box.bottom,
                         width: window.innerWidth, height: window.innerHeight,
                         text: document.getElementById('info').textContent };
  }
  if (request.slider !== undefined) {
    window.mdlcSetPositions(opened);
    const before = window.mdlcShownPoses();
    const input = sliders.find((s) => s.input.dataset.joint === request.slider).input;
    input.value = request.value;
    input.dispatchEvent(new Event('input'));
    const after = window.mdlcShownPoses();
    report.moved = model.bodies.map((b) => b.scoped_name).filter((name, i) =>
      Math.max(...after[i].R.map((x, k) => Math.abs(x - before[i].R[k])),
               ...after[i].p.map((x, k) => Math.abs(x - before[i].p[k]))) > 1e-9);
    window.mdlcSetPositions(opened);
  }
  report.errors = window.mdlcErrors ?? [];
  const pre = document.createElement('pre');
  pre.id = 'mdlc-selftest';
  pre.textContent = JSON.stringify(report);
  document.body.append(pre);
}
document.body.dataset.ready = 'true';
