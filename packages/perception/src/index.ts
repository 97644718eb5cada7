export { ColourDetector } from './colour-detector.js';
export type { ColourDetectorOptions } from './colour-detector.js';
export { decodeFrame, defaultJpegDecoder, frameBytes, jpegJsDecoder } from './decode.js';
export { loadSharpDecoder } from './sharp-decoder.js';
export type { JpegDecoder } from './image.js';
export type { Detector, DetectorInput } from './detector.js';
export { FloorModel } from './floor-model.js';
export type { FloorModelOptions } from './floor-model.js';
export { FramePerceiver } from './frame-perceiver.js';
export type { FramePerceiverOptions, Percept } from './frame-perceiver.js';
export { DEFAULT_FREE_SPACE, scanFreeSpace } from './free-space.js';
export type { FreeSpaceColumn, FreeSpaceOptions } from './free-space.js';
export type { RgbaImage } from './image.js';
export {
  COLOUR_NAMES,
  ColourTable,
  colourLabel,
  colourOf,
  DEFAULT_COLOUR_THRESHOLDS,
  DEFAULT_PALETTE,
  OFF_PALETTE,
} from './palette.js';
export type { ColourName, ColourThresholds, PaletteColour } from './palette.js';
export { projectDetection, toWorld } from './project-object.js';
export type { Detection } from './project-object.js';
export type { ImageBox, ObjectKind, SeenObject } from './seen-object.js';
export { clearanceAhead } from './clearance.js';
export type { Clearance } from './clearance.js';
export { integrateFreeSpace } from './grid-fusion.js';
export type { FreeSpaceFusionOptions } from './grid-fusion.js';
export { ObjectMemory } from './object-memory.js';
export type { ObjectMemoryOptions, RememberedObject } from './object-memory.js';
export { Perception } from './perception.js';
export type { Look, PerceptionOptions } from './perception.js';
export { VisionModelDetector } from './vlm-detector.js';
export type { VisionModelDetectorOptions, VlmDetectionReport } from './vlm-detector.js';
export { VisionModelDetectorOptionsSchema } from './vlm-options.js';
export type { VlmFailure } from './vlm-errors.js';
export { readLabel, VLM_KINDS } from './vlm-labels.js';
export type { VlmKind } from './vlm-labels.js';
export { VLM_REPLY_JSON_SCHEMA, vlmInstruction } from './vlm-prompt.js';
export type { VlmResponseFormat } from './vlm-prompt.js';
export type { VlmBoxUnits, VlmReplyCounts } from './vlm-reply.js';
export { scanWithCamera, withCameraScan } from './camera-scan.js';
export { perceivingObserver } from './observer.js';
export type { PerceivingObserverOptions } from './observer.js';
export { GuardedHAL, guardHal } from './guard/guarded-hal.js';
export { GuardSettingsSchema, guardSettings } from './guard/guard-settings.js';
export type { GuardOptions, GuardSettings } from './guard/guard-settings.js';
export type { GuardEvent, GuardListener, GuardStatus, GuardStop } from './guard/guard-status.js';
export type { GuardSource, Sighting } from './guard/sighting.js';
export { GuardEventSchema, GuardStopSchema } from './guard/guard-event-schema.js';
