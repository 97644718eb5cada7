// Every tool @hal/tools can offer: the whole catalog, from a simulated robot that claims every
// capability a tool requires (speaker, arm...), so no tool is left out for a missing one.
import type { ChatTool } from '@hal/agent';
import { SimulationHAL, World } from '@hal/simulation';
import { halTools, TOOL_CATALOG, toOpenAITools } from '@hal/tools';
import type { HalTool } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';

/** The catalog's tools, every one of them, for a simulated robot. */
export function everyHalTool(): HalTool[] {
  const sim = new SimulationHAL({ world: new World() });
  const capabilities = [
    ...new Set(
      TOOL_CATALOG.flatMap((entry) => (entry.requires === undefined ? [] : [entry.requires])),
    ),
  ];
  const info = sim.getDeviceInfo();
  // halTools reads only the robot's limits and its capabilities (a SimulationHAL's own methods
  // cannot be borrowed by another object: they read its private fields)
  const hal = {
    robotConfig: sim.robotConfig,
    getDeviceInfo: () => ({ ...info, capabilities: [...info.capabilities, ...capabilities] }),
  } as unknown as HardwareAbstractionLayer;
  const tools = halTools(hal);
  if (tools.length !== TOOL_CATALOG.length)
    throw new Error(`expected all ${TOOL_CATALOG.length} tools, got ${tools.length}`);
  return tools;
}

/** {@link everyHalTool} in the chat format the providers get. */
export function everyChatTool(): ChatTool[] {
  return toOpenAITools(everyHalTool());
}
