#include "dds/entity.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

namespace envdesign::dds {

bool security_configured() {
    const char *uri = std::getenv("CYCLONEDDS_URI");
    if (!uri)
        return false;
    std::string text = uri;
    std::string all = text;
    std::stringstream parts(text);
    for (std::string part; std::getline(parts, part, ',');) {
        auto start = part.find_first_not_of(" \t");
        if (start == std::string::npos || part.compare(start, 7, "file://") != 0)
            continue;
        std::ifstream file(part.substr(start + 7));
        all += std::string(std::istreambuf_iterator<char>(file), {});
    }
    return all.find("<Security") != std::string::npos;
}

DdsError::DdsError(const std::string &what, dds_return_t code)
    : std::runtime_error(what + ": " + dds_strretcode(-code)), code_(code) {}

dds_return_t check(dds_return_t rc, const char *what) {
    if (rc < 0)
        throw DdsError(what, rc);
    return rc;
}

Entity::Entity(dds_entity_t handle, const char *what) : handle_(check(handle, what)) {}

Entity::~Entity() { reset(); }

Entity::Entity(Entity &&other) noexcept : handle_(std::exchange(other.handle_, 0)) {}

Entity &Entity::operator=(Entity &&other) noexcept {
    if (this != &other) {
        reset();
        handle_ = std::exchange(other.handle_, 0);
    }
    return *this;
}

void Entity::reset() noexcept {
    // ALREADY_DELETED / BAD_PARAMETER: a parent took it along; nothing else can fail here,
    // and a destructor must not throw.
    if (handle_ > 0)
        dds_delete(handle_);
    handle_ = 0;
}

Qos::Qos() : qos_(dds_create_qos()) {
    if (!qos_)
        throw DdsError("create QoS", DDS_RETCODE_OUT_OF_RESOURCES);
}

Qos::~Qos() {
    if (qos_)
        dds_delete_qos(qos_);
}

Qos::Qos(Qos &&other) noexcept : qos_(std::exchange(other.qos_, nullptr)) {}

} // namespace envdesign::dds
