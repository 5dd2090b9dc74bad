#include "app/tracking/dtrack_receiver.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <vector>

#include "core/tracking/dtrack_parser.h"
#include "core/tracking/ipv4_address.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

namespace {

[[noreturn]] void fail(int fd, const std::string& what) {
  const std::string why = std::strerror(errno);
  if (fd >= 0) ::close(fd);
  throw Error(concat(what, ": ", why));
}

constexpr int kLoggedDrops = 3;  // reasons logged in full; later drops are counted

// An address the configuration already checked (core/config); checked again
// here for a receiver made in code.
std::uint32_t address(const std::string& text, const char* setting) {
  const std::optional<std::uint32_t> a = parseIpv4(text);
  if (!a) throw Error(concat(setting, ": '", text, "' is not an IPv4 address"));
  return *a;
}

std::string listed(const std::vector<std::string>& addresses) {
  std::string out;
  for (const std::string& a : addresses)
    out += (out.empty() ? "" : ", ") + a;
  return out;
}

}  // namespace

DTrackReceiver::DTrackReceiver(Options options) : options_(std::move(options)) {
  for (const std::string& s : options_.senders)
    senders_.push_back(address(s, "tracking.sender"));
  const std::uint32_t local = options_.interfaceAddress.empty()
                                  ? INADDR_ANY
                                  : address(options_.interfaceAddress, "tracking.interface");
  const std::string where = concat("tracking.port ", options_.port);
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) fail(fd, where + ": cannot open a UDP socket");
  in_addr group{};
  if (!options_.multicast.empty()) {
    if (::inet_pton(AF_INET, options_.multicast.c_str(), &group) != 1 ||
        !IN_MULTICAST(ntohl(group.s_addr))) {
      ::close(fd);
      throw Error(
          concat("tracking.multicast: '", options_.multicast, "' is not an IPv4 multicast group"));
    }
    // Several programs may listen to one multicast stream.
    const int yes = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  }
  const int size = 1 << 20;  // room for bursts at 300 Hz while a frame stalls
  ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &size, sizeof size);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(std::uint16_t(options_.port));
  // A multicast group is received on a socket bound to any address; the
  // interface then picks where the group is joined.
  address.sin_addr.s_addr = htonl(options_.multicast.empty() ? local : INADDR_ANY);
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0)
    fail(fd, concat("tracking: cannot listen on UDP port ", options_.port,
                    options_.interfaceAddress.empty() ? "" : " of " + options_.interfaceAddress,
                    errno == EADDRINUSE ? " (another program uses it; is a second Sandstorm "
                                          "running? set [tracking] port)"
                    : errno == EADDRNOTAVAIL
                        ? " (no interface has that address; set [tracking] interface)"
                        : ""));
  if (!options_.multicast.empty()) {
    ip_mreq request{};
    request.imr_multiaddr = group;
    request.imr_interface.s_addr = htonl(local);
    if (::setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &request, sizeof request) != 0)
      fail(fd, concat("tracking: cannot join multicast group ", options_.multicast, " on port ",
                      options_.port));
  }
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  socket_ = fd;
  thread_ = std::thread([this] { run(); });
  log::info("tracking: listening for DTrack on UDP port ", port_,
            options_.multicast.empty() ? "" : " (multicast " + options_.multicast + ")",
            options_.interfaceAddress.empty() ? "" : " of " + options_.interfaceAddress,
            senders_.empty() ? "" : ", from " + listed(options_.senders) + " only");
  if (senders_.empty())
    log::warn(
        "tracking: tracking.sender is not set, so datagrams from any host on the "
        "network move the head and the wand and click the menu; set tracking.sender to "
        "the DTrack controller's address");
}

DTrackReceiver::~DTrackReceiver() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  if (socket_ >= 0) ::close(socket_);
}

void DTrackReceiver::run() {
  // One byte more than the largest datagram we read: a longer one shows as truncated.
  std::vector<char> buffer(DTrackLimits::kMaxDatagram + 1);
  pollfd waiting{socket_, POLLIN, 0};
  while (!stop_) {
    const int ready = ::poll(&waiting, 1, 50);  // wake up to notice stop_
    if (ready <= 0) continue;
    sockaddr_in from{};
    socklen_t fromLength = sizeof from;
    const ssize_t n = ::recvfrom(socket_, buffer.data(), buffer.size(), MSG_TRUNC | MSG_DONTWAIT,
                                 reinterpret_cast<sockaddr*>(&from), &fromLength);
    if (n < 0) continue;
    const double arrival = steadySeconds();
    const std::uint32_t sender = ntohl(from.sin_addr.s_addr);
    if (!senders_.empty() &&
        std::find(senders_.begin(), senders_.end(), sender) == senders_.end()) {
      refuse(sender);
      continue;
    }
    if (std::size_t(n) > DTrackLimits::kMaxDatagram) {
      drop(concat("DTrack datagram: ", n, " bytes exceed the limit of ",
                  DTrackLimits::kMaxDatagram));
      continue;
    }
    take(std::string_view(buffer.data(), std::size_t(n)), arrival);
  }
}

void DTrackReceiver::take(std::string_view datagram, double arrival) {
  TrackerFrame frame;
  try {
    frame = parseDTrack(datagram);
  } catch (const Error& e) {
    drop(e.what());
    return;
  }
  std::lock_guard lock(mutex_);
  ++stats_.received;
  newest_ = TrackerMeasurement{std::move(frame), stats_.received, arrival};
}

void DTrackReceiver::drop(const std::string& why) {
  std::uint64_t dropped;
  {
    std::lock_guard lock(mutex_);
    dropped = ++stats_.dropped;
    stats_.lastError = why;
  }
  if (dropped <= kLoggedDrops)
    log::warn("tracking: dropped a datagram: ", why,
              dropped == kLoggedDrops ? " (further drops are counted in the stats)" : "");
  else
    log::debug("tracking: dropped a datagram: ", why);
}

void DTrackReceiver::refuse(std::uint32_t sender) {
  std::uint64_t foreign;
  {
    std::lock_guard lock(mutex_);
    foreign = ++stats_.foreign;
  }
  if (foreign == 1)
    log::warn("tracking: dropped a datagram from ", formatIpv4(sender),
              ", which is not in tracking.sender (", listed(options_.senders),
              "); further ones are counted in the stats");
}

std::optional<TrackerMeasurement> DTrackReceiver::newest() const {
  std::lock_guard lock(mutex_);
  return newest_;
}

TrackerStats DTrackReceiver::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

std::string DTrackReceiver::describe() const {
  return concat("DTrack on UDP port ", port_,
                options_.multicast.empty() ? "" : " (multicast " + options_.multicast + ")");
}

}  // namespace sandstorm
