import type { HALLogLevel, SafetyStatus } from '@hal/types';
import type { MotionReport } from '../robot/motion-report.js';

/** Something the HAL's communication subsystem did, for a UI to show. */
export type CommunicationEvent =
  | { type: 'led'; r: number; g: number; b: number; pattern: 'solid' | 'blink' | 'pulse' }
  | { type: 'speak'; text: string; urgency: 'info' | 'warning' | 'alert' }
  | { type: 'sound'; soundId: string }
  | { type: 'log'; message: string; level: HALLogLevel; atMs: number };

/** Everything a SimulationHAL reports as it happens. */
export interface SimulationHALEvents extends Record<string, unknown> {
  communication: CommunicationEvent;
  /** A motion started (firmware command issued). */
  motionStarted: MotionReport;
  /** A motion ended, with its outcome. */
  motionFinished: MotionReport;
  /** The emergency stop latched or cleared. */
  safety: SafetyStatus;
}
