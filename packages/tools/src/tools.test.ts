import { PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { toAnthropicTools, toJsonSchemas, toMcpTools, toOpenAITools } from './formats.js';
import { halTools } from './tools.js';

const names = (hal: Parameters<typeof halTools>[0]) => halTools(hal).map((t) => t.name);

describe('halTools', () => {
  it('offers capture_frame only to a robot with a camera', async () => {
    const withCamera = new SimulationHAL();
    const without = new SimulationHAL({ features: { camera: false, rangeSensors: false } });
    await withCamera.initialize();
    await without.initialize();
    expect(names(withCamera)).toContain('capture_frame');
    expect(names(withCamera)).toContain('scan');
    expect(names(without)).not.toContain('capture_frame');
    expect(names(without)).not.toContain('scan');
    expect(names(without)).not.toContain('get_distance_sensors');
    expect(names(without)).toEqual(
      expect.arrayContaining(['move_forward', 'get_pose', 'stop', 'emergency_stop']),
    );
  });

  it('offers a PhysicalHAL over the mock robot what the V1 cube reported: no camera, speaker or range sensors', async () => {
    const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-1' },
      { transport: robot.transport(), timeScale: 50 },
    );
    await hal.initialize();
    const offered = names(hal);
    expect(offered).toEqual(
      expect.arrayContaining(['move_forward', 'rotate', 'set_led', 'get_imu', 'emergency_stop']),
    );
    for (const absent of ['capture_frame', 'speak', 'play_sound', 'scan', 'get_distance_sensors']) {
      expect(offered).not.toContain(absent);
    }
    await hal.cleanup();
  });

  it('always offers stop and emergency_stop, even to a robot that reports nothing', () => {
    const sim = new SimulationHAL();
    // a HAL of its own, with no robotConfig (V1 limits) and no capabilities
    const bare: HardwareAbstractionLayer = {
      mode: 'simulation',
      locomotion: sim.locomotion,
      vision: sim.vision,
      communication: sim.communication,
      safety: sim.safety,
      initialize: () => sim.initialize(),
      cleanup: () => sim.cleanup(),
      isReady: () => sim.isReady(),
      getDeviceInfo: () => ({ id: 'bare', type: 'bare', mode: 'simulation', capabilities: [] }),
    };
    expect(names(bare)).toEqual(expect.arrayContaining(['stop', 'emergency_stop', 'get_pose']));
    expect(names(bare)).not.toContain('move_forward');
    expect(halTools(bare).find((t) => t.name === 'emergency_stop')?.inputSchema).toMatchObject({
      properties: { reason: { type: 'string' } },
    });
  });

  it("takes the parameter bounds from the robot's own limits", async () => {
    const v1 = new SimulationHAL();
    const short = new SimulationHAL({
      robot: { maxStepsPerCommand: 4096, workspaceHalfExtentM: 5 },
    });
    const bound = (hal: SimulationHAL, tool: string, prop: string) =>
      halTools(hal).find((t) => t.name === tool)?.inputSchema.properties[prop];
    expect(bound(v1, 'move_forward', 'distanceCm')).toMatchObject({
      exclusiveMinimum: 0,
      maximum: 188.4,
    });
    expect(bound(short, 'move_forward', 'distanceCm')).toMatchObject({ maximum: 18.8 });
    expect(bound(short, 'move_to', 'x')).toMatchObject({ minimum: -5, maximum: 5 });
    expect(halTools(short).find((t) => t.name === 'move_forward')?.description).toMatch(
      /at most 18\.8/,
    );
  });

  it('filters by include and exclude', () => {
    const hal = new SimulationHAL();
    expect(names(hal)).toContain('rotate');
    expect(halTools(hal, { include: ['get_pose', 'rotate'] }).map((t) => t.name)).toEqual([
      'rotate',
      'get_pose',
    ]);
    expect(halTools(hal, { exclude: ['drive'] }).map((t) => t.name)).not.toContain('drive');
  });

  it('describes every tool with units and the REP-103 frame where it moves or reads a pose', () => {
    const tools = halTools(new SimulationHAL());
    for (const tool of tools) {
      expect(tool.name).toMatch(/^[a-z]+(_[a-z]+)*$/);
      expect(tool.inputSchema.type).toBe('object');
      expect(tool.description.length).toBeGreaterThan(20);
    }
    const text = (name: string) => tools.find((t) => t.name === name)?.description ?? '';
    expect(text('move_to')).toMatch(/REP-103.*metres/);
    expect(text('get_pose')).toMatch(/REP-103.*metres.*radians/);
    expect(text('rotate')).toMatch(/degrees/);
  });

  it('exports the same tools in the OpenAI, Anthropic, MCP and plain JSON Schema forms', () => {
    const tools = halTools(new SimulationHAL(), { include: ['move_forward', 'get_pose'] });
    const schema = tools[0]?.inputSchema;
    expect(toOpenAITools(tools)[0]).toEqual({
      type: 'function',
      function: { name: 'move_forward', description: tools[0]?.description, parameters: schema },
    });
    expect(toAnthropicTools(tools)[1]).toMatchObject({
      name: 'get_pose',
      input_schema: { type: 'object' },
    });
    expect(toMcpTools(tools)[0]).toEqual({
      name: 'move_forward',
      description: tools[0]?.description,
      inputSchema: schema,
    });
    expect(Object.keys(toJsonSchemas(tools))).toEqual(['move_forward', 'get_pose']);
    expect(JSON.stringify(toOpenAITools(tools))).not.toContain('$schema');
  });
});
