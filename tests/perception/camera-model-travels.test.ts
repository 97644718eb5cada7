// The camera model travels with the robot: each HAL reports the model its frames are taken with
// in getDeviceInfo (the simulator the one it renders with; a physical robot its configured or
// calibrated one; none without a camera), the forwarding HALs pass it on, and Perception projects
// with it when it is given none.
import { Perception } from '@hal/perception';
import { HybridHAL } from '@hal/hybrid';
import { PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import { RemoteHAL } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import { DeviceInfoSchema, V1_CAMERA } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';

const TILTED = { ...V1_CAMERA, tiltDeg: 15, heightM: 0.12 };

const cleanups: Array<() => Promise<void>> = [];
afterEach(async () => {
  for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
});

function own<T extends HardwareAbstractionLayer>(hal: T): T {
  cleanups.push(() => hal.cleanup());
  return hal;
}

function physical(config: { cameraUrl?: string; camera?: object }, calibration?: object) {
  const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000, deviceId: 'cube-7' });
  const { camera, cameraUrl } = config;
  return own(
    new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-7',
        connection: { type: 'wifi', host: '127.0.0.1', ...(cameraUrl ? { cameraUrl } : {}) },
        ...(camera === undefined ? {} : { camera }),
      },
      {
        transport: robot.transport(),
        timeScale: 50,
        ...(calibration === undefined ? {} : { calibration: () => calibration }),
      },
    ),
  );
}

describe('the camera model in the device info', () => {
  it('is the one the simulator renders with, and absent when it has no camera', () => {
    const sim = own(new SimulationHAL({ camera: { tiltDeg: 15, heightM: 0.12, maxDistanceM: 4 } }));
    expect(sim.getDeviceInfo().camera).toEqual(TILTED);
    expect(DeviceInfoSchema.parse(sim.getDeviceInfo()).camera).toEqual(TILTED);
    expect(own(new SimulationHAL()).getDeviceInfo().camera).toEqual(V1_CAMERA);
    const configured = own(
      SimulationHAL.fromConfig({
        mode: 'simulation',
        deviceId: 'sim-cam',
        camera: { tiltDeg: 15, heightM: 0.12 },
      }),
    );
    expect(configured.getDeviceInfo().camera).toEqual(TILTED);
    const blind = own(new SimulationHAL({ features: { camera: false } }));
    expect(blind.getDeviceInfo().camera).toBeUndefined();
  });

  it("is a physical robot's configured model, V1's by default, none without a camera URL", () => {
    const url = 'http://127.0.0.1:9';
    expect(physical({ cameraUrl: url }).getDeviceInfo().camera).toEqual(V1_CAMERA);
    expect(
      physical({ cameraUrl: url, camera: { tiltDeg: 15, heightM: 0.12 } }).getDeviceInfo().camera,
    ).toEqual(TILTED);
    expect(physical({ camera: { tiltDeg: 15 } }).getDeviceInfo().camera).toBeUndefined();
  });

  it("is a physical robot's calibrated model once its hello named it, over the configured one", async () => {
    const hal = physical(
      { cameraUrl: 'http://127.0.0.1:9', camera: { tiltDeg: 30 } },
      { camera: TILTED },
    );
    expect(hal.getDeviceInfo().camera?.tiltDeg).toBe(30);
    await hal.initialize();
    expect(hal.getDeviceInfo().camera).toEqual(TILTED);
  });

  it('passes through a served HAL to a RemoteHAL, and through a HybridHAL', async () => {
    const sim = own(new SimulationHAL({ camera: { tiltDeg: 15, heightM: 0.12 } }));
    const server = await serveHal(sim, { port: 0 });
    cleanups.push(() => server.close());
    const remote = own(new RemoteHAL({ url: server.url, reconnect: false }));
    await remote.initialize();
    expect(remote.getDeviceInfo().camera).toEqual(TILTED);

    const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000 });
    const body = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-1',
        connection: { type: 'wifi', host: '127.0.0.1', cameraUrl: 'http://127.0.0.1:9' },
        camera: { tiltDeg: 15, heightM: 0.12 },
      },
      { transport: robot.transport(), timeScale: 50 },
    );
    const hybrid = own(new HybridHAL({ physical: body, twin: new SimulationHAL() }));
    expect(hybrid.getDeviceInfo().camera).toEqual(TILTED);
  });
});

describe('Perception', () => {
  it("projects with the robot's camera model when it is given none, and with its own when given", () => {
    const sim = own(new SimulationHAL({ camera: { tiltDeg: 15, heightM: 0.12 } }));
    expect(new Perception(sim).perceiver.camera).toEqual(TILTED);
    expect(new Perception(sim, { camera: { tiltDeg: 25 } }).perceiver.camera.tiltDeg).toBe(25);
    const blind = own(new SimulationHAL({ features: { camera: false } }));
    expect(new Perception(blind).perceiver.camera).toEqual(V1_CAMERA);
  });
});
