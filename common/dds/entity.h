#pragma once
// Overview: Cyclone DDS's C API from C++ (there is no cyclonedds-cxx in Debian 12).
//
// Every entity (participant, topic, reader, writer, waitset, condition) is held by an
// Entity, which calls dds_delete when it goes; every QoS by a Qos, which calls
// dds_delete_qos. Every return code is checked: a negative one becomes a DdsError naming
// the call and dds_strretcode's text. Deleting a participant deletes its children, so
// classes holding several entities declare the participant first (destroyed last) and the
// children's own dds_delete then finds them gone, which is not an error.
//
// Example:
//   Entity participant(dds_create_participant(domain, nullptr, nullptr), "create participant");
//   Qos qos;
//   check(... , "set QoS");
//
// The arrivals topic (arrival_topic.h) is built from these.
//
// Naming: common/ is on the include path, so a file here named like one of Cyclone's
// top-level headers (dds/dds.h, config.h, export.h, features.h, version.h) would shadow it.

#include <dds/dds.h>

#include <stdexcept>
#include <string>

namespace envdesign::dds {

class DdsError : public std::runtime_error {
public:
    DdsError(const std::string &what, dds_return_t code);
    dds_return_t code() const { return code_; }

private:
    dds_return_t code_;
};

// `rc` when it is not negative; otherwise throws DdsError "WHAT: <dds_strretcode>".
dds_return_t check(dds_return_t rc, const char *what);

// Whether Cyclone's configuration ($CYCLONEDDS_URI: inline XML, or file:// paths, comma
// separated) has a <Security> section (DDS Security: authenticated, access-controlled
// participants). Without it anyone on the domain can publish; the bridge says so at start.
bool security_configured();

// Owns one DDS entity handle; move-only.
class Entity {
public:
    Entity() = default;
    // Takes `handle` (checked: a negative one throws DdsError naming `what`).
    Entity(dds_entity_t handle, const char *what);
    ~Entity();
    Entity(Entity &&other) noexcept;
    Entity &operator=(Entity &&other) noexcept;
    Entity(const Entity &) = delete;
    Entity &operator=(const Entity &) = delete;

    dds_entity_t get() const { return handle_; }
    explicit operator bool() const { return handle_ > 0; }

private:
    void reset() noexcept;
    dds_entity_t handle_ = 0;
};

// Owns a dds_qos_t; move-only.
class Qos {
public:
    Qos();
    ~Qos();
    Qos(Qos &&other) noexcept;
    Qos &operator=(Qos &&other) = delete;
    Qos(const Qos &) = delete;
    Qos &operator=(const Qos &) = delete;

    dds_qos_t *get() const { return qos_; }

private:
    dds_qos_t *qos_;
};

} // namespace envdesign::dds
