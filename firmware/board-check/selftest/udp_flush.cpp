// Must NOT compile under the board check's flags: NetworkUDP::flush() is
// deprecated in the 3.x core ("Use clear() instead."), and from 3.0.0 to
// 3.0.4 it left the received datagram in the buffer. ctest's
// BoardCheck.RefusesTheDeprecatedUdpFlush expects the deprecation error.
#include <WiFiUdp.h>

void DropDatagram(WiFiUDP& udp) { udp.flush(); }
