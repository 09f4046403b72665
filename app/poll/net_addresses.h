// The machine's IPv4 addresses, for the lecturer to pick the one phones can reach: the panel
// lists them, the one on the interface of the default route first (the classroom's network,
// usually), loopback last (this machine only).
#pragma once

#include <string>
#include <vector>

struct NetAddress {
    std::string interface; // "wlan0"
    std::string address;   // "192.168.1.5"
    bool defaultRoute = false;
    bool loopback = false;
};

// Every IPv4 address of an interface that is up, default route first, loopback last.
std::vector<NetAddress> netAddresses();
// The address a poll binds by default: the default route's, else the first listed, else
// "127.0.0.1".
std::string defaultPollAddress();
