#include "net_addresses.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>

namespace {

// The interfaces of default routes (destination 0.0.0.0), from /proc/net/route.
std::vector<std::string> defaultRouteInterfaces() {
    std::vector<std::string> names;
    std::ifstream routes("/proc/net/route");
    std::string line;
    std::getline(routes, line); // the header
    while (std::getline(routes, line)) {
        std::istringstream fields(line);
        std::string name, destination;
        if (fields >> name >> destination && destination == "00000000") names.push_back(name);
    }
    return names;
}

} // namespace

std::vector<NetAddress> netAddresses() {
    std::vector<NetAddress> list;
    ifaddrs* all = nullptr;
    if (getifaddrs(&all) != 0) return list;
    const std::vector<std::string> defaults = defaultRouteInterfaces();
    for (const ifaddrs* a = all; a; a = a->ifa_next) {
        if (!a->ifa_addr || a->ifa_addr->sa_family != AF_INET || !(a->ifa_flags & IFF_UP)) continue;
        char text[INET_ADDRSTRLEN] = {};
        const auto* in = reinterpret_cast<const sockaddr_in*>(a->ifa_addr);
        if (!inet_ntop(AF_INET, &in->sin_addr, text, sizeof text)) continue;
        NetAddress n;
        n.interface = a->ifa_name ? a->ifa_name : "";
        n.address = text;
        n.loopback = (a->ifa_flags & IFF_LOOPBACK) != 0;
        n.defaultRoute = std::find(defaults.begin(), defaults.end(), n.interface) != defaults.end();
        list.push_back(n);
    }
    freeifaddrs(all);
    std::stable_sort(list.begin(), list.end(), [](const NetAddress& a, const NetAddress& b) {
        auto rank = [](const NetAddress& n) { return n.defaultRoute ? 0 : n.loopback ? 2 : 1; };
        return rank(a) < rank(b);
    });
    return list;
}

std::string defaultPollAddress() {
    const std::vector<NetAddress> list = netAddresses();
    return list.empty() ? "127.0.0.1" : list.front().address;
}
