#include "dds/socket_buffers.hpp"

#include <algorithm>
#include <fstream>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fmt/format.h>

namespace gdnav::dds {

std::uint32_t udp_receive_buffer_asked(const eprosima::fastdds::dds::DomainParticipant& p) {
    std::uint32_t asked = 0;
    for (const auto& t : p.get_qos().transport().user_transports)
        if (const auto* udp = dynamic_cast<const eprosima::fastdds::rtps::UDPv4TransportDescriptor*>(t.get()))
            asked = std::max(asked, udp->receiveBufferSize);
    return asked;
}

std::uint64_t kernel_receive_buffer_cap(const std::filesystem::path& rmem_max_file) {
    std::ifstream in(rmem_max_file);
    std::uint64_t cap = 0;
    if (!(in >> cap)) return 0;
    return cap;
}

std::string receive_buffer_shortfall(std::uint32_t asked, std::uint64_t cap) {
    if (asked == 0 || cap == 0 || cap >= asked) return {};
    return fmt::format("UDP receive buffers capped at {} bytes by net.core.rmem_max (the DDS profile asks for {}): "
                       "bursts of samples may be dropped and wait for repair, slowing the run; raise it with "
                       "`sysctl -w net.core.rmem_max={}`",
                       cap, asked, asked);
}

}  // namespace gdnav::dds
