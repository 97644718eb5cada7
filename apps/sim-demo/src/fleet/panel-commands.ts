import type { FleetCommand } from '@hal/fleet';
import { motionCall } from '@hal/types';

/** The fleet command of the HAL's straight drive that way, `n` cm. */
const straight =
  (motion: 'forward' | 'backward') =>
  (n: number): FleetCommand => ({ kind: motionCall(motion).name, distanceCm: n });

/** The commands the Fleet card offers: what the amount field means, and the fleet command. */
export const PANEL_COMMANDS = {
  forward: {
    label: 'Forward',
    unit: 'cm',
    initial: 20,
    command: straight('forward'),
  },
  backward: {
    label: 'Backward',
    unit: 'cm',
    initial: 20,
    command: straight('backward'),
  },
  left: {
    label: 'Turn left',
    unit: '°',
    initial: 90,
    command: (n: number): FleetCommand => ({ kind: 'rotate', direction: 'left', degrees: n }),
  },
  right: {
    label: 'Turn right',
    unit: '°',
    initial: 90,
    command: (n: number): FleetCommand => ({ kind: 'rotate', direction: 'right', degrees: n }),
  },
  drive: {
    label: 'Drive ahead',
    unit: 's',
    initial: 3,
    // Power 200 of 255 on both wheels for n seconds.
    command: (n: number): FleetCommand => ({
      kind: 'drive',
      left: 200,
      right: 200,
      durationMs: Math.round(n * 1000),
    }),
  },
} as const;

export type PanelCommandName = keyof typeof PANEL_COMMANDS;

/** The command `name` with `amount`: bad amounts are left to the HALs, which refuse them. */
export function panelCommand(name: PanelCommandName, amount: number): FleetCommand {
  return PANEL_COMMANDS[name].command(amount);
}

/** One line for a command, for the results list and the log. */
export function describeCommand(name: PanelCommandName, amount: number): string {
  const { label, unit } = PANEL_COMMANDS[name];
  return `${label} ${amount} ${unit}`;
}
