// The command script both agreement tests run (the simulated robot against the emulated firmware,
// and against the mock robot), and the one way a wire command is given to the simulated robot.
import type { SimRobot } from '@hal/simulation';

/** A wire command, as protocol section 5 writes it (`cmd` and its fields). */
export type Command = Record<string, string | number>;

/** Straight moves, turns both ways, arcs, raw steps, slower speeds and a drive. */
export const AGREEMENT_SCRIPT: readonly Command[] = [
  { cmd: 'move_cm', left_cm: 10, right_cm: 10 },
  { cmd: 'rotate_deg', degrees: 90 },
  { cmd: 'move_cm', left_cm: 12.34, right_cm: 12.34 },
  { cmd: 'rotate_deg', degrees: -45 },
  { cmd: 'move_cm', left_cm: 5, right_cm: 15 },
  { cmd: 'move_steps', left: 1000, right: -500, speed: 600 },
  { cmd: 'move_cm', left_cm: 3.3, right_cm: 3.3, speed: 300 },
  { cmd: 'drive', left_sps: 800, right_sps: 600, duration_ms: 1500 },
  { cmd: 'rotate_deg', degrees: 200.5 },
  { cmd: 'move_cm', left_cm: -7.77, right_cm: -7.77 },
];

/** Gives `command` to the simulated robot; a refusal throws as the robot throws it. */
export function commandSimRobot(robot: SimRobot, command: Command): void {
  const n = (key: string) => Number(command[key]);
  const speed = command['speed'] === undefined ? undefined : n('speed');
  switch (command['cmd']) {
    case 'move_cm':
      robot.moveCm(n('left_cm'), n('right_cm'), speed);
      break;
    case 'rotate_deg':
      robot.rotateDeg(n('degrees'), speed);
      break;
    case 'move_steps':
      robot.moveSteps(n('left'), n('right'), speed);
      break;
    case 'drive':
      robot.drive(n('left_sps'), n('right_sps'), n('duration_ms'));
      break;
    case 'reset_estop':
      robot.resetEmergencyStop();
      break;
    default:
      throw new Error(`the script has an unknown command ${String(command['cmd'])}`);
  }
}
