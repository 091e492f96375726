#pragma once
// Decimated mirrors of the data topics, for observers (docs/protocol.md §2.2, docs/runtime.md "Mirrors for the
// observers"). Every gdnav host also writes each data output of step k with k % kMirrorStride == 0 on a topic of its
// own, mirror_topic(topic), of the same type and the data QoS — only while a reader is matched on it, so a run
// without observers writes nothing more. An observer (the live bridge) whose input has a stride that is a multiple
// of kMirrorStride reads the mirror instead of the topic when reads_mirror() says every producer writes one: then
// the producers' writers of the topic itself never see it, and deliver exactly what the run's own readers need.
// (The writer-side stride filter, dds/filters/stride_filter.hpp, delivers fewer samples too, but Fast DDS 2.9 still
// sends a filtered reader GAPs and HEARTBEATs, and splits the writer's datagrams to the other readers; a mirror's
// readers cost the topic's writers nothing: docs/notes/runtime-measurements.md, "Mirrors for the observers".)
// Only gdnav's own hosts write mirrors: a producer run outside gdnav (an external member, another DDS vendor) need
// not, so an observer reads the topic itself when any producer of it is external or not in the run's configuration.
// Secure runs do not use mirrors (a PKI grants each identity its own topics, not mirrors of them).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dds/compat.hpp"

namespace gdnav::dds {

inline constexpr std::uint64_t kMirrorStride = 10;

// "gdnav/Truth" -> "gdnav/Truth/every_10_steps".
std::string mirror_topic(const std::string& topic);

// Whether an observer's input of `stride` could read a mirror at all (a multiple of kMirrorStride, not a secure
// run): such an input gets its reader only at CONFIGURE, when reads_mirror() can be answered.
bool may_read_mirror(std::uint64_t stride, bool secure);

// Whether an observer's input of `stride` reads the mirror of its topic. producers: the names of the members that
// write the topic (the clock's member table); writes_mirror(name): that member is a gdnav host in another process
// (a configured, non-external component of the run, not hosted by the observer's own process).
bool reads_mirror(std::uint64_t stride, bool secure, const std::vector<std::string>& producers,
                  const std::function<bool(const std::string&)>& writes_mirror);

}  // namespace gdnav::dds
