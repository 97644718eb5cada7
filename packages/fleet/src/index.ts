// Browser-safe: no Node imports and no NATS. The device manager is in '@hal/fleet/node'.
export { Fleet } from './fleet.js';
export type { FleetOptions } from './fleet.js';

export { FLEET_MODES } from './report.js';
export type { FleetMode, FleetReport, MemberResult } from './report.js';

export {
  FleetCommandSchema,
  fleetCommandSchema,
  parseFleetCommand,
  runFleetCommand,
} from './commands.js';
export type { FleetCommand } from './commands.js';

export type { FleetMember } from './members.js';

export type { MemberCall, SynchronizedOptions } from './synchronized.js';

export { LeaderFollower } from './leader-follower.js';
export type {
  FollowerReport,
  FormationEndReason,
  FormationReport,
  LeaderFollowerOptions,
} from './leader-follower-options.js';
export { FORMATION_SHAPES, formationOffsets } from './formation.js';
export type { FormationOffset, FormationShape } from './formation.js';

export { SteppedScheduler, realTimeScheduler } from './scheduler.js';
export type { FleetScheduler } from './scheduler.js';
