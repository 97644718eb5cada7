// The DNS-SD service a HAL robot announces (the firmware's src/core/announce.h holds the same
// names): `_hal-cube._udp.local`, on the robot's UDP port.

/** The service name, without the leading underscore (bonjour-service adds it). */
export const SERVICE_NAME = 'hal-cube';
/** The service's transport label. */
export const SERVICE_PROTOCOL = 'udp';
/** The TXT record layout this package reads and writes (`txtvers`). */
export const TXT_VERSION = '1';
/** Longest `key=value` of one TXT entry, bytes: its length is one byte on the wire (RFC 6763 6.1). */
export const MAX_TXT_ENTRY_BYTES = 255;
