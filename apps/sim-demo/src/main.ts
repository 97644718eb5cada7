import './style.css';
import { BUILTIN_MAPS, readDistanceSensors, SimulationHAL, World } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import { createThreeFrameSource, fromThree, toThree, WorldScene } from '@hal/simulation/three';
import type { HALToolResult } from '@hal/types';
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GoalSeekingProvider, NavigationBridge, OccupancyGrid } from '@hal/navigation';
import { TrajectoryPlot } from './plot.js';
import { powersFor, TELEOP_KEYS } from './teleop.js';

function element<T extends HTMLElement>(id: string): T {
  const found = document.getElementById(id);
  if (found === null) throw new Error(`#${id} is missing from the page`);
  return found as T;
}

// ---- the world, its view and the robot's HAL ---------------------------------------------------

const params = new URLSearchParams(location.search);
const mapNames = Object.keys(BUILTIN_MAPS) as BuiltinMapName[];
const requestedMap = params.get('map');
let mapName: BuiltinMapName = mapNames.includes(requestedMap as BuiltinMapName)
  ? (requestedMap as BuiltinMapName)
  : 'obstacles';
const requestedSpeed = Number(params.get('speed') ?? '5');
const speed = [1, 2, 5, 10, 20].includes(requestedSpeed) ? requestedSpeed : 5;

const world = new World({ map: mapName, seed: 1 });
world.startRealtime({ speed });
const view = new WorldScene(world, { showRangeRays: true });
const robotCamera = createThreeFrameSource(view, { canvas: element('camera-view') });
const hal = new SimulationHAL({ world, clock: 'realtime', frameSource: robotCamera.frameSource });
await hal.initialize();
const robotId = hal.robot.id;

// ---- the 3D viewport -----------------------------------------------------------------------------

const viewport = element<HTMLElement>('viewport');
const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.shadowMap.enabled = true;
renderer.shadowMap.type = THREE.PCFShadowMap;
viewport.prepend(renderer.domElement);
const camera = new THREE.PerspectiveCamera(45, 1, 0.05, 200);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = true;
controls.maxPolarAngle = Math.PI / 2 - 0.05;
controls.minDistance = 0.4;
controls.maxDistance = 25;

function frameArena(): void {
  const { width, height } = world.map.arena;
  const size = Math.max(width, height);
  camera.position.copy(toThree(-size * 0.05, -size * 0.95, size * 1.05));
  controls.target.set(0, 0, 0);
  controls.update();
}
frameArena();

function resize(): void {
  const { clientWidth: w, clientHeight: h } = viewport;
  renderer.setSize(w, h, false);
  renderer.domElement.style.width = `${w}px`;
  renderer.domElement.style.height = `${h}px`;
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}
new ResizeObserver(resize).observe(viewport);
resize();

// ---- status, results log -------------------------------------------------------------------------

const status = element<HTMLElement>('status');
const log = element<HTMLOListElement>('log');

function setStatus(text: string, tone: 'info' | 'ok' | 'bad' = 'info'): void {
  status.textContent = text;
  status.className = `status${tone === 'info' ? '' : ` ${tone}`}`;
}

function record(call: string, result: HALToolResult): void {
  const item = document.createElement('li');
  item.className = result.success ? 'pass' : 'fail';
  const secs = ((result.executionTime ?? 0) / 1000).toFixed(1);
  item.textContent = result.success
    ? `${call} ✓ (${secs} s simulated)`
    : `${call} ✗ ${result.code}: ${result.error}`;
  log.prepend(item);
  while (log.children.length > 30) log.lastElementChild?.remove();
}

function note(text: string): void {
  const item = document.createElement('li');
  item.className = 'event';
  item.textContent = text;
  log.prepend(item);
  while (log.children.length > 30) log.lastElementChild?.remove();
}
hal.events.on('communication', (e) => {
  if (e.type === 'led') note(`LED ${e.pattern} rgb(${e.r}, ${e.g}, ${e.b})`);
  else if (e.type === 'log') note(`log [${e.level}] ${e.message}`);
  else if (e.type === 'speak') note(`says "${e.text}"`);
  else note(`plays ${e.soundId}`);
});
hal.events.on('motionFinished', (m) => {
  if (m.outcome === 'collision' && m.contact !== undefined) {
    const p = m.contact.point;
    note(`bumped into a ${m.contact.role} at (${p.x.toFixed(2)}, ${p.y.toFixed(2)}) m`);
  } else if (m.outcome === 'host_timeout') {
    note('host timeout: the robot stopped by itself');
  }
});

// ---- goals: click the floor --------------------------------------------------------------------
// With "Plan around obstacles" the navigation bridge drives there (A* on an occupancy grid seeded
// with the map, re-planning from the range sensors); without it, one straight moveTo.

type GoalState = 'none' | 'driving' | 'reached' | 'failed' | 'cancelled';
let goal: { x: number; y: number } | undefined;
let goalState: GoalState = 'none';
let goalSerial = 0;
let plannedPath: Array<{ x: number; y: number }> | undefined;

const planToggle = element<HTMLInputElement>('plan-toggle');
const gridToggle = element<HTMLInputElement>('grid-toggle');
let grid = OccupancyGrid.fromMap(world.map);
let bridge = makeBridge();

function makeBridge(): NavigationBridge {
  const made = new NavigationBridge({ hal, provider: new GoalSeekingProvider(), grid });
  made.on('path', ({ plan }) => {
    const robot = hal.robot;
    plannedPath = [{ x: robot.x, y: robot.y }, ...plan.waypoints.slice(1)];
    view.setPlannedPath(plannedPath);
  });
  made.on('result', ({ call, args, result }) => {
    const text = Object.values(args)
      .map((v) => (typeof v === 'number' ? Number(v.toFixed(2)) : String(v)))
      .join(', ');
    record(`${call}(${text})`, result);
  });
  return made;
}

/** The occupancy grid as the scene's overlay wants it: occupancy 0..1, negative unknown. */
function showGrid(): void {
  if (!gridToggle.checked) {
    view.setOccupancyGrid(undefined);
    return;
  }
  const { spec, logOdds } = grid;
  const data = Array.from(logOdds, (l) => (l === 0 ? -1 : 1 / (1 + Math.exp(-l))));
  view.setOccupancyGrid({
    width: spec.width,
    height: spec.height,
    resolution: spec.resolutionM,
    origin: { x: spec.originX, y: spec.originY },
    data,
  });
}

/** Stops whatever is driving to a goal (and waits until it has). */
async function cancelGoal(): Promise<void> {
  if (goalState === 'driving') goalState = 'cancelled';
  goalSerial += 1;
  goal = undefined;
  plannedPath = undefined;
  view.setGoal(undefined);
  view.setPlannedPath(undefined);
  await bridge.stop();
}

async function goTo(x: number, y: number): Promise<void> {
  await cancelGoal();
  const serial = goalSerial;
  goal = { x, y };
  goalState = 'driving';
  const robot = hal.robot;
  view.setGoal(goal);
  const where = `(${x.toFixed(2)}, ${y.toFixed(2)}) m`;
  let ok: boolean;
  let why: string;
  if (planToggle.checked) {
    setStatus(`Planning a route to ${where}…`);
    const outcome = await bridge.run({ x, y });
    ok = outcome.status === 'reached';
    why = `${outcome.reason}: ${outcome.message}`;
  } else {
    plannedPath = [
      { x: robot.x, y: robot.y },
      { x, y },
    ];
    view.setPlannedPath(plannedPath);
    setStatus(`Driving straight to ${where}…`);
    const result = await hal.locomotion.moveTo(x, y, 0);
    record(`moveTo(${x.toFixed(2)}, ${y.toFixed(2)})`, result);
    ok = result.success;
    why = `${result.code ?? ''}: ${result.error ?? ''}`;
  }
  if (serial !== goalSerial) return;
  view.setPlannedPath(undefined);
  plannedPath = undefined;
  if (ok) {
    goalState = 'reached';
    setStatus('Goal reached ✓', 'ok');
  } else {
    goalState = 'failed';
    setStatus(`Stopped: ${why}`, 'bad');
  }
}

const floor = new THREE.Plane(new THREE.Vector3(0, 1, 0), 0);
const raycaster = new THREE.Raycaster();
let pressedAt: { x: number; y: number } | undefined;
renderer.domElement.addEventListener('pointerdown', (e) => {
  pressedAt = { x: e.clientX, y: e.clientY };
});
renderer.domElement.addEventListener('pointerup', (e) => {
  if (pressedAt === undefined || e.button !== 0) return;
  const moved = Math.hypot(e.clientX - pressedAt.x, e.clientY - pressedAt.y);
  pressedAt = undefined;
  if (moved > 5) return; // a drag orbits the view
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(
    ((e.clientX - rect.left) / rect.width) * 2 - 1,
    -((e.clientY - rect.top) / rect.height) * 2 + 1,
  );
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.ray.intersectPlane(floor, new THREE.Vector3());
  if (hit === null) return;
  const p = fromThree(hit);
  const { width, height } = world.map.arena;
  if (Math.abs(p.x) > width / 2 || Math.abs(p.y) > height / 2) {
    setStatus('That point is outside the arena', 'bad');
    return;
  }
  void goTo(p.x, p.y);
});

// ---- keyboard teleop -----------------------------------------------------------------------------

const held = new Set<string>();
let lastDrive = '';

// Teleop actions run one after another, each for the keys held when it runs, so a quick release
// can never be overtaken by the drive it ends.
let teleopChain: Promise<void> = Promise.resolve();
function applyTeleop(): void {
  teleopChain = teleopChain.then(teleopNow).catch(() => undefined);
}

async function teleopNow(): Promise<void> {
  const powers = powersFor(held);
  const signature = JSON.stringify(powers ?? null);
  if (signature === lastDrive) return;
  lastDrive = signature;
  if (powers === undefined) {
    record('stop()', await hal.locomotion.stop());
    setStatus('Stopped');
    return;
  }
  if (goalState === 'driving') await cancelGoal();
  setStatus(`Driving: left ${powers.left}, right ${powers.right}`);
  const result = await hal.locomotion.drive(powers.left, powers.right);
  if (!result.success) {
    record(`drive(${powers.left}, ${powers.right})`, result);
    setStatus(`${result.code}: ${result.error ?? ''}`, 'bad');
  }
}

function keyName(e: KeyboardEvent): string {
  return e.key.length === 1 ? e.key.toLowerCase() : e.key;
}

window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLSelectElement) return;
  const key = keyName(e);
  if (key === 'Escape') {
    void emergencyStop();
    return;
  }
  if (key === ' ') {
    e.preventDefault();
    held.clear();
    lastDrive = 'null';
    void hal.locomotion.stop().then((r) => record('stop()', r));
    void cancelGoal();
    setStatus('Stopped');
    return;
  }
  if (!TELEOP_KEYS.has(key)) return;
  e.preventDefault();
  if (!held.has(key)) {
    held.add(key);
    applyTeleop();
  }
});
window.addEventListener('keyup', (e) => {
  const key = keyName(e);
  if (held.delete(key)) applyTeleop();
});
window.addEventListener('blur', () => {
  if (held.size === 0) return;
  held.clear();
  applyTeleop();
});

// ---- buttons and menus ---------------------------------------------------------------------------

const estopButton = element<HTMLButtonElement>('estop-button');
async function emergencyStop(): Promise<void> {
  held.clear();
  if (hal.safety.isEmergencyStopped()) {
    record('resetEmergencyStop()', await hal.safety.resetEmergencyStop());
    setStatus('Emergency stop cleared');
  } else {
    record('emergencyStop()', await hal.safety.emergencyStop('stop button in the demo'));
    setStatus('EMERGENCY STOP latched: motion is refused until you reset it', 'bad');
    await cancelGoal();
  }
  lastDrive = '';
}
estopButton.addEventListener('click', () => void emergencyStop());

const plotCanvas = element<HTMLCanvasElement>('plot');
const plot = new TrajectoryPlot(plotCanvas);
plotCanvas.addEventListener('click', (e) => {
  const p = plot.toWorld(e.clientX, e.clientY);
  const { width, height } = world.map.arena;
  if (Math.abs(p.x) <= width / 2 && Math.abs(p.y) <= height / 2) void goTo(p.x, p.y);
});
async function resetWorld(name: BuiltinMapName): Promise<void> {
  await cancelGoal();
  goalState = 'none';
  held.clear();
  lastDrive = '';
  mapName = name;
  world.setMap(name);
  hal.simulateHostSilence(silentToggle.checked);
  grid = OccupancyGrid.fromMap(world.map);
  bridge = makeBridge();
  showGrid();
  plot.clear();
  if (followToggle.checked) startFollowing();
  else frameArena();
  setStatus(`Map "${name}": ${BUILTIN_MAPS[name].description}`);
}

const mapSelect = element<HTMLSelectElement>('map-select');
for (const name of mapNames) {
  const option = document.createElement('option');
  option.value = name;
  option.textContent = name[0]?.toUpperCase() + name.slice(1);
  mapSelect.append(option);
}
mapSelect.value = mapName;
mapSelect.addEventListener('change', () => {
  void resetWorld(mapSelect.value as BuiltinMapName);
  mapSelect.blur();
});
element<HTMLButtonElement>('reset-button').addEventListener(
  'click',
  () => void resetWorld(mapName),
);

const speedSelect = element<HTMLSelectElement>('speed-select');
speedSelect.value = String(speed);
speedSelect.addEventListener('change', () => {
  world.startRealtime({ speed: Number(speedSelect.value) });
  speedSelect.blur();
});

planToggle.addEventListener('change', () => planToggle.blur());
gridToggle.addEventListener('change', () => {
  gridToggle.blur();
  showGrid();
});

const silentToggle = element<HTMLInputElement>('silent-toggle');
silentToggle.addEventListener('change', () => {
  silentToggle.blur();
  hal.simulateHostSilence(silentToggle.checked);
  note(
    silentToggle.checked
      ? `host silent: a motion stops ${hal.robot.config.hostTimeoutMs} ms after the last command`
      : 'host talking again',
  );
});

const followToggle = element<HTMLInputElement>('follow-toggle');
let followed: THREE.Vector3 | undefined;
followToggle.addEventListener('change', () => {
  followToggle.blur();
  if (followToggle.checked) {
    startFollowing();
  } else {
    followed = undefined;
    frameArena();
  }
});

function startFollowing(): void {
  // Close behind the robot, looking where it goes; then keep that offset as it moves.
  const robot = hal.robot;
  followed = toThree(robot.x, robot.y);
  controls.target.copy(followed);
  camera.position.copy(
    toThree(robot.x - 0.9 * Math.cos(robot.yaw), robot.y - 0.9 * Math.sin(robot.yaw), 0.6),
  );
  controls.update();
}

function follow(): void {
  if (followed === undefined) return;
  const robot = hal.robot;
  const now = toThree(robot.x, robot.y);
  const delta = now.clone().sub(followed);
  camera.position.add(delta);
  controls.target.add(delta);
  followed = now;
}

const ledInput = element<HTMLInputElement>('led-input');
ledInput.addEventListener('change', async () => {
  const hex = Number.parseInt(ledInput.value.slice(1), 16);
  const [r, g, b] = [(hex >> 16) & 255, (hex >> 8) & 255, hex & 255];
  record(`setLED(${r}, ${g}, ${b})`, await hal.communication.setLED(r, g, b, 'solid'));
  ledInput.blur();
});

// ---- telemetry -----------------------------------------------------------------------------------

const telemetry = element<HTMLElement>('telemetry');
const badge = element<HTMLElement>('safety-badge');
const rows = new Map<string, HTMLElement>();
function row(label: string, value: string): void {
  let dd = rows.get(label);
  if (dd === undefined) {
    const dt = document.createElement('dt');
    dt.textContent = label;
    dd = document.createElement('dd');
    telemetry.append(dt, dd);
    rows.set(label, dd);
  }
  if (dd.textContent !== value) dd.textContent = value;
}

function showTelemetry(): void {
  const robot = hal.robot;
  const v = robot.velocity();
  const wheels = robot.wheelSpeeds();
  const motion = robot.motion;
  const ranges = readDistanceSensors(world, robot);
  row('Sim time', `${(world.nowUs / 1e6).toFixed(1)} s`);
  row('Position', `x ${robot.x.toFixed(3)} m, y ${robot.y.toFixed(3)} m`);
  row('Heading', `${((robot.yaw * 180) / Math.PI).toFixed(1)}°`);
  row(
    'Speed',
    `${(v.linear * 100).toFixed(2)} cm/s, ${((v.angular * 180) / Math.PI).toFixed(1)}°/s`,
  );
  row('Wheel steps', `L ${robot.leftSteps}, R ${robot.rightSteps}`);
  row('Wheel speed', `L ${Math.round(wheels.left)}, R ${Math.round(wheels.right)} steps/s`);
  row('Motion', motion === undefined ? '–' : `#${motion.moveId} ${motion.kind}: ${motion.outcome}`);
  row(
    'Range F/L/R',
    `${ranges.front.toFixed(2)} / ${ranges.left.toFixed(2)} / ${ranges.right.toFixed(2)} m`,
  );
  const led = robot.led;
  row('LED', led.pattern === 'off' ? 'off' : `rgb(${led.r}, ${led.g}, ${led.b}) ${led.pattern}`);
  const trip = robot.lastTrip;
  row(
    'Last trip',
    trip === undefined ? 'none' : `${trip.reason} at ${(trip.atUs / 1e6).toFixed(1)} s`,
  );
  if (robot.emergencyStopped) {
    badge.textContent = 'E-STOP LATCHED';
    badge.className = 'badge bad';
    estopButton.textContent = 'RESET E-STOP';
    estopButton.classList.add('latched');
  } else {
    badge.textContent = motion?.outcome === 'running' ? 'MOVING' : 'SAFE';
    badge.className = `badge ${motion?.outcome === 'running' ? 'warn' : 'ok'}`;
    estopButton.textContent = 'E-STOP';
    estopButton.classList.remove('latched');
  }
}

// ---- the frame loop ------------------------------------------------------------------------------

let lastTelemetry = 0;
let shownGridVersion = -1;
function frame(now: number): void {
  follow();
  controls.update();
  view.update();
  renderer.render(view.scene, camera);
  robotCamera.render(robotId);
  const robot = hal.robot;
  plot.record(robot.x, robot.y);
  plot.draw(world, robotId, goal, plannedPath);
  if (gridToggle.checked && grid.version !== shownGridVersion) {
    shownGridVersion = grid.version;
    showGrid();
  }
  if (now - lastTelemetry > 100) {
    lastTelemetry = now;
    showTelemetry();
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
setStatus(`Map "${mapName}": ${BUILTIN_MAPS[mapName].description}`);

/** Hooks for the end-to-end test and for curious people at the console. */
const hooks = {
  hal,
  world,
  robotId,
  goalState: (): GoalState => goalState,
  pose: () => ({ x: hal.robot.x, y: hal.robot.y, yaw: hal.robot.yaw }),
  /** Where a world point (metres) is on the screen, in client pixels. */
  worldToClient: (x: number, y: number) => {
    const p = toThree(x, y).project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return {
      x: rect.left + ((p.x + 1) / 2) * rect.width,
      y: rect.top + ((1 - p.y) / 2) * rect.height,
    };
  },
};
(window as unknown as { simDemo: typeof hooks }).simDemo = hooks;
