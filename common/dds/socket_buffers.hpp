#pragma once
// The UDP socket receive buffers a participant asked for against what the kernel grants (net.core.rmem_max caps
// SO_RCVBUF silently). A buffer smaller than the profile's makes a burst of samples overflow it; each lost datagram
// then waits for a repair (docs/runtime.md, "Socket receive buffers").
#include <cstdint>
#include <filesystem>
#include <string>

#include "dds/compat.hpp"

namespace eprosima::fastdds::dds {
class DomainParticipant;
}

namespace gdnav::dds {

// The largest receiveBufferSize of the participant's UDPv4 transports (0: none asked for, the system default).
[[nodiscard]] std::uint32_t udp_receive_buffer_asked(const eprosima::fastdds::dds::DomainParticipant& p);

// The kernel's cap read from `rmem_max_file` (0 when it cannot be read).
[[nodiscard]] std::uint64_t kernel_receive_buffer_cap(
    const std::filesystem::path& rmem_max_file = "/proc/sys/net/core/rmem_max");

// One line for the run's log when the cap is below what the participant asked for, else empty.
[[nodiscard]] std::string receive_buffer_shortfall(std::uint32_t asked, std::uint64_t cap);

}  // namespace gdnav::dds
