export { DEFAULT_DISCOVERY_TIMEOUT_MS, discoverRobots, findRobot } from './discover.js';
export type { DiscoveredRobot, DiscoverOptions } from './discover.js';
export { createPhysicalHALFromDiscovery, physicalHalConfigFor } from './physical.js';
export type { DiscoveredConnectionOptions } from './physical.js';
export { announceRobot } from './announce.js';
export type { AnnounceOptions, Announcer } from './announce.js';
export type { MdnsOptions } from './mdns-socket.js';
export { SERVICE_NAME, SERVICE_PROTOCOL, SERVICE_TYPE } from './service.js';
export { ANNOUNCED_AUTH, AnnouncementTxtSchema, parseAnnouncementTxt } from './txt-record.js';
export type { AnnouncedAuth, ParsedAnnouncement, RobotAnnouncement } from './txt-record.js';
export {
  TAFY_NODE_PROTOCOL,
  TAFY_NODE_SERVICE,
  TAFY_NODE_TYPE,
  announceTafyNode,
  discoverTafyNodes,
} from './tafy-node.js';
export type { FoundTafyNode, TafyNodeAnnouncement, TafyNodeAnnouncer } from './tafy-node.js';
