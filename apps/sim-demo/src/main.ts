import './style.css';
import { BUILTIN_MAPS, World } from '@hal/simulation';
import { createThreeFrameSource, WorldScene } from '@hal/simulation/three';
import { DemoControls } from './demo-controls.js';
import { DemoFleet } from './fleet/demo-fleet.js';
import { FleetPanel } from './fleet/fleet-panel.js';
import { fleetLogger } from './fleet/fleet-logger.js';
import { element } from './dom.js';
import { FrameSchedule } from './frame-schedule.js';
import { GoalDriver } from './goal-driver.js';
import { KeyboardTeleop } from './keyboard-teleop.js';
import { TrajectoryPlot } from './plot.js';
import { AgentPanel } from './panels/agent-panel.js';
import { PerceptionView } from './perception/perception-view.js';
import { noteHalEvents, ResultsLog } from './results-log.js';
import { RobotLabels } from './robots/robot-labels.js';
import { RobotsCard } from './robots/robots-card.js';
import { RobotRoster } from './robots/roster.js';
import { selectedHal } from './robots/selected-hal.js';
import { StatusLine } from './status-line.js';
import { TelemetryPanel } from './telemetry-panel.js';
import { RecordingPanel } from './recording/recording-panel.js';
import { SessionRecorder } from './recording/session-recorder.js';
import { RemotePanel } from './remote-panel.js';
import { chooseRenderProfile, webglRendererName } from './render-profile.js';
import { readUrlSettings } from './url-settings.js';
import { Viewport } from './viewport.js';

/*
 * The browser demo: builds the world, its 3D scene and the robots' HALs, puts the page's panels
 * together, and runs the frame loop. Each panel lives in its own module.
 */

// ---- the world, its view and the robots' HALs ------------------------------------------------

const { mapName, speed, robots: robotCount, render } = readUrlSettings(location.search);
const rendererName = webglRendererName();
const renderProfile = chooseRenderProfile(render, rendererName, window.devicePixelRatio);
const world = new World({ map: mapName, seed: 1 });
world.startRealtime({ speed });
const colors = new Map<string, string>();
const scene = new WorldScene(world, { showRangeRays: true, robotColor: (id) => colors.get(id) });
const robotCamera = createThreeFrameSource(scene, {
  canvas: element('camera-view'),
  antialias: renderProfile.antialias,
  shadows: renderProfile.shadows,
});
const roster = await RobotRoster.create({ world, frameSource: robotCamera.frameSource });
// Every robot has its own HAL; the panels hold this one, which is always the selected robot's
// (through its recorder while the Recording card records it).
const sessions = new SessionRecorder();
const hal = selectedHal(() => sessions.halFor(roster.selected.hal));

// ---- the panels ----------------------------------------------------------------------------------

const viewport = new Viewport(element('viewport'), world, () => hal.robot, renderProfile);
const status = new StatusLine(element('status'));
const log = new ResultsLog(element('log'));
let currentMap: string = mapName;
const recording = new RecordingPanel(element('recording-card'), {
  sessions,
  scene,
  selectedHal: () => roster.selected.hal,
  mapName: () => currentMap,
  cameraCanvas: element<HTMLCanvasElement>('camera-view'),
  status,
  onPlaybackChange: (playing) => {
    // the live robots' labels go with their hidden models
    document.body.classList.toggle('playing-back', playing);
    if (!playing) return;
    // The live robot is left as it was: no goal goes on, no key drives it.
    void goals.cancel();
    teleop.releaseKeys();
  },
});

const planToggle = element<HTMLInputElement>('plan-toggle');
const gridToggle = element<HTMLInputElement>('grid-toggle');
const goals = new GoalDriver({
  hal,
  scene,
  log,
  status,
  planAroundObstacles: () => planToggle.checked,
  // while Perception runs, the floor shows the grid it perceives instead
  showGrid: () => gridToggle.checked && !perception.enabled,
});
const perception = new PerceptionView({
  hal,
  scene,
  toggle: element('perception-toggle'),
  overlay: element('camera-overlay'),
  list: element('perception-list'),
  onOff: () => goals.showGrid(),
});

/** Sends the robot to a clicked point when it is inside the arena. */
function clickedGoal(p: { x: number; y: number }, outside: () => void): void {
  const { width, height } = world.map.arena;
  if (recording.playingBack) status.set('Playing back a recording: "Back to live" to drive', 'bad');
  else if (Math.abs(p.x) > width / 2 || Math.abs(p.y) > height / 2) outside();
  else void goals.goTo(p.x, p.y);
}
viewport.onFloorClick((p) =>
  clickedGoal(p, () => status.set('That point is outside the arena', 'bad')),
);

const teleop = new KeyboardTeleop({ hal, goals, log, status, paused: () => recording.playingBack });
teleop.attach(window);

const plotCanvas = element<HTMLCanvasElement>('plot');
const plot = new TrajectoryPlot(plotCanvas);
plotCanvas.addEventListener('click', (e) =>
  clickedGoal(plot.toWorld(e.clientX, e.clientY), () => undefined),
);

new DemoControls({
  hal,
  setMap: (name) => {
    currentMap = name;
    roster.resetWorld(name);
  },
  goals,
  teleop,
  viewport,
  plot,
  log,
  status,
  mapName,
  speed,
  planToggle,
  gridToggle,
});

const agent = new AgentPanel(element('agent-panel'), hal);

const telemetry = new TelemetryPanel({
  list: element('telemetry'),
  badge: element('safety-badge'),
  estopButton: element('estop-button'),
});

const remote = new RemotePanel(element('remote-card'), hal, log);

// ---- several robots: colours, labels, events, and the robot the panels drive --------------------

const robotsCard = new RobotsCard(element('robots-card'), roster, status);
const fleet = new FleetPanel(
  element('fleet-card'),
  new DemoFleet(roster, fleetLogger(log)),
  roster,
  log,
  status,
);
const labels = new RobotLabels(roster, viewport);
const noted = new Map<string, () => void>();
let driven = roster.selected;
function robotsChanged(): void {
  fleet.robotsChanged();
  for (const robot of roster.robots) {
    colors.set(robot.id, robot.color);
    if (!noted.has(robot.id)) noted.set(robot.id, noteHalEvents(robot.hal, log, robot.label));
  }
  for (const [id, off] of noted) {
    if (!roster.robots.some((r) => r.id === id)) {
      off();
      noted.delete(id);
    }
  }
  if (roster.selected !== driven) {
    // The goal and the keys belonged to the robot driven until now.
    driven = roster.selected;
    // A fresh occupancy grid too: the old one was mapped by the other robot's sensors.
    void goals.cancel().then(() => goals.startOver());
    teleop.releaseKeys();
    teleop.forgetLastDrive();
    plot.clear();
    status.set(`Driving ${driven.label}`);
  }
}
roster.onChange(robotsChanged);
robotsChanged();
for (let i = 1; i < robotCount; i += 1) await roster.add();

// ---- the frame loop ------------------------------------------------------------------------------

// Frames are drawn on demand: when the scene changed (a robot moved, a path, goal or map was set,
// a recording is playing back), when the view moved, and once a second whatever happens. A page
// left open with nothing moving then costs next to nothing, and a moving robot is drawn every
// frame, or under the light render profile (WebGL drawn in software) at most five times a
// second: a change then waits for the next frame due and is drawn with it.
const frames = new FrameSchedule({
  minIntervalMs: renderProfile.minFrameIntervalMs,
  idleRedrawMs: 1000,
});
/** Draws the 3D view and moves the robots' labels over it. */
function drawView(): void {
  viewport.render(scene.scene);
  labels.update();
}
// A resized canvas is blank until drawn again: draw it at once, not on the next frame due.
viewport.onResized(() => {
  frames.drewOutOfTurn();
  drawView();
});
let lastTelemetry = 0;
function frame(now: number): void {
  scene.update();
  goals.refreshGrid();
  recording.frame(now);
  const robot = hal.robot;
  plot.record(robot.x, robot.y);
  const viewMoved = viewport.update();
  const draw = frames.next(now, viewMoved, `${scene.revision} ${recording.revision} ${robot.id}`);
  if (draw.view) drawView();
  if (draw.scene) {
    robotCamera.render(robot.id);
    plot.draw(world, robot.id, goals.goal, goals.plannedPath, (id) => colors.get(id));
  }
  if (now - lastTelemetry > 100) {
    lastTelemetry = now;
    telemetry.show(world, hal.robot);
    robotsCard.refresh();
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
status.set(
  `Map "${mapName}": ${BUILTIN_MAPS[mapName].description}` +
    (renderProfile.name === 'light' ? ` · light rendering: ${renderProfile.reason}` : ''),
);

/** Hooks for the end-to-end test and for curious people at the console. */
const hooks = {
  hal,
  world,
  roster,
  /** The id of the robot the panels drive. */
  get robotId() {
    return roster.selected.id;
  },
  goalState: () => goals.state,
  remote: () => remote.state,
  agentRunning: () => agent.running,
  /** The Recording card: a recording running, a playback and where it draws the robot. */
  recording: () => recording.state,
  pose: () => ({ x: hal.robot.x, y: hal.robot.y, yaw: hal.robot.yaw }),
  /** How many frames of the 3D view were drawn (on demand: see the frame loop). */
  framesDrawn: () => frames.framesDrawn,
  /** How the 3D view is drawn (`?render=`), and the WebGL renderer the browser reports. */
  render: () => ({ ...renderProfile, rendererName }),
  /** Every robot's id, label, pose and e-stop state, by number. */
  robots: () =>
    roster.robots.map(({ id, label, hal: { robot } }) => ({
      id,
      label,
      x: robot.x,
      y: robot.y,
      yaw: robot.yaw,
      running: robot.running,
      emergencyStopped: robot.emergencyStopped,
    })),
  /** The Perception toggle: looks taken, the objects of the last one, the perceived grid's cells. */
  perception: () => perception.state,
  /** The Fleet card's mode, last per-robot results, formation and fleet e-stop. */
  fleet: () => fleet.state,
  /** While a formation runs: each follower's distance to its slot, metres. */
  slotErrors: () => fleet.slotErrors(),
  /** Where a world point (metres) is on the screen, in client pixels. */
  worldToClient: (x: number, y: number) => viewport.worldToClient(x, y),
};
(window as unknown as { simDemo: typeof hooks }).simDemo = hooks;
