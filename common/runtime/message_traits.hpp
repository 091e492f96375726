#pragma once
// Type-erased operations on IDL message types, so executors and the recorder can move, stamp and serialise
// samples of any topic without knowing their C++ type. A message type is made known with
// GDNAV_DECLARE_MESSAGE(Type, PubSubType) at global scope (all gdnav::msg types are declared in messages.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include <fastdds/dds/topic/TopicDataType.hpp>

namespace gdnav::runtime {

template <class T>
struct PubSubTypeOf;  // specialised by GDNAV_DECLARE_MESSAGE

struct MessageOps {
    const char* type_name;
    eprosima::fastdds::dds::TopicDataType* (*make_type)();
    void* (*create)();
    void (*destroy)(void*);
    void (*copy)(void* dst, const void* src);
    // Sets stamp (run id, step, time) on samples that carry one (no-op otherwise).
    void (*set_stamp)(void* sample, std::uint64_t run_id, std::uint64_t step, double t_s);
    // Step and run of a stamped sample (UINT64_MAX for unstamped types).
    std::uint64_t (*step_of)(const void* sample);
    std::uint64_t (*run_of)(const void* sample);
    // CDR encoding with zeroed padding: identical samples give identical bytes.
    void (*serialize)(const void* sample, std::vector<std::uint8_t>& out);
};

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
        }};
    return ops;
}
}  // namespace detail

template <class T>
const MessageOps& message_ops() {
    return detail::make_ops<T>();
}

}  // namespace gdnav::runtime

#define GDNAV_DECLARE_MESSAGE(T, PS)                  \
    template <>                                       \
    struct gdnav::runtime::PubSubTypeOf<T> {          \
        using type = PS;                              \
        static constexpr const char* name = #T;       \
    };
