#pragma once
// The definition of message_ops<T>() on Fast DDS type support. Included only by the translation units that declare
// message types (msgs/messages.cpp, msgs/viewer_messages.cpp, a test's own types), each type once, at global scope:
//   GDNAV_DECLARE_MESSAGE(gdnav::msg::Truth, gdnav::msg::TruthPubSubType)
// which explicitly instantiates message_ops<Type>() there; everybody else sees only msgs/message_ops.hpp.
#include <algorithm>
#include <cstring>
#include <exception>

#include <fastdds/dds/topic/TopicDataType.hpp>

#include "msgs/message_ops.hpp"

namespace gdnav::msg {

template <class T>
struct PubSubTypeOf;  // specialised by GDNAV_DECLARE_MESSAGE

namespace detail {
template <class T>
concept Stamped = requires(T t) {
    t.stamp().step();
    t.stamp().run_id();
    t.stamp().t_s();
};

template <class T>
const MessageOps& make_ops() {
    using PS = typename PubSubTypeOf<T>::type;
    static const MessageOps ops{
        PubSubTypeOf<T>::name,
        []() -> eprosima::fastdds::dds::TopicDataType* { return new PS(); },
        []() -> void* { return new T(); },
        [](void* p) { delete static_cast<T*>(p); },
        [](void* d, const void* s) { *static_cast<T*>(d) = *static_cast<const T*>(s); },
        [](void* p, std::uint64_t run, std::uint64_t step, double t) {
            if constexpr (Stamped<T>) {
                auto& st = static_cast<T*>(p)->stamp();
                st.run_id(run);
                st.step(step);
                st.t_s(t);
            }
        },
        [](const void* p) -> std::uint64_t {
            if constexpr (Stamped<T>) return static_cast<const T*>(p)->stamp().step();
            return UINT64_MAX;
        },
        [](const void* p) -> std::uint64_t {
            if constexpr (Stamped<T>) return static_cast<const T*>(p)->stamp().run_id();
            return UINT64_MAX;
        },
        [](const void* p, std::vector<std::uint8_t>& out) {
            // Called per recorded sample: the type support and the payload buffer are reused (per thread).
            thread_local PS ps;
            thread_local eprosima::fastrtps::rtps::SerializedPayload_t payload;
            void* data = const_cast<void*>(p);
            const std::uint32_t size = ps.getSerializedSizeProvider(data)();
            if (payload.max_size < size) payload.reserve(size);
            std::fill(payload.data, payload.data + size, std::uint8_t{0});
            payload.length = 0;
            payload.pos = 0;
            ps.serialize(data, &payload);
            out.assign(payload.data, payload.data + payload.length);
        },
        [](const std::uint8_t* bytes, std::uint32_t n, void* sample) -> bool {
            thread_local PS ps;
            thread_local eprosima::fastrtps::rtps::SerializedPayload_t payload;
            if (payload.max_size < n) payload.reserve(n);
            std::memcpy(payload.data, bytes, n);
            payload.length = n;
            payload.pos = 0;
            try {
                return ps.deserialize(&payload, sample);
            } catch (const std::exception&) {
                return false;  // Fast CDR throws on payloads shorter than the type
            }
        },
        [](const void* p) -> double {
            if constexpr (Stamped<T>) return static_cast<const T*>(p)->stamp().t_s();
            return 0.0;
        }};
    return ops;
}
}  // namespace detail

template <class T>
const MessageOps& message_ops() {
    return detail::make_ops<T>();
}

}  // namespace gdnav::msg

#define GDNAV_DECLARE_MESSAGE(T, PS)                                    \
    template <>                                                         \
    struct gdnav::msg::PubSubTypeOf<T> {                                \
        using type = PS;                                                \
        static constexpr const char* name = #T;                         \
    };                                                                  \
    template const gdnav::msg::MessageOps& gdnav::msg::message_ops<T>();
