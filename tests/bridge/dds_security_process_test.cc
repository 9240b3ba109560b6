// Cyclone DDS Security on the arrivals topic (deploy/LAN.md "DDS"): Debian's Cyclone ships
// the authentication, access control and crypto plugins, so arrivals are authenticated by
// certificates of the deployment's CA (deploy/dds-security). A publisher with a certificate
// reaches the bridge; one without is never matched and none of its arrivals count.

#include "harness.h"

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

std::vector<std::string> secure_env(const std::string &pki, const std::string &name) {
    return {"CYCLONEDDS_URI=file://" + SOURCE + "/deploy/dds-security/cyclonedds-secure.xml",
            "ENVDESIGN_DDS_PKI=" + pki, "ENVDESIGN_DDS_NAME=" + name,
            "ENVDESIGN_DDS_PLUGINS=/usr/lib/x86_64-linux-gnu/libddsc0debian"};
}

std::unique_ptr<Process> arrivals(const std::string &dir, const std::string &replay,
                                  std::vector<std::string> env, const std::string &log) {
    return std::make_unique<Process>(
        std::vector<std::string>{BIN + "/envdesign-arrivals", "--replay", replay, "--problem",
                                 "restaurant", "--domain", "69", "--rate", "2000", "--wait-bridge",
                                 "4"},
        env, dir + "/" + log);
}

TEST(DdsSecurity, OnlyPublishersWithACertificateReachTheBridge) {
    std::string dir = scratch("dds-security");
    std::string pki = dir + "/pki";
    ASSERT_EQ(std::system(("bash " + SOURCE + "/deploy/dds-security/make-pki.sh " + pki +
                           " bridge arrivals >/dev/null")
                              .c_str()),
              0);
    Listener lcm(lcm_url(7769));
    Process bridge({BIN + "/envdesign-bridge", "--problem", "restaurant=" + DRIFT_SPEC, "--domain",
                    "69", "--lcm-url", lcm_url(7769), "--name", "bridge/test", "--publish-hz", "50",
                    "--estimator", "window:100"},
                   secure_env(pki, "bridge"), dir + "/bridge.log");
    std::string replay = write_replay(dir + "/mix.csv", "task", booth_mix(150, 9));

    auto outsider = arrivals(dir, replay, dds_env(), "outsider.log");
    EXPECT_EQ(outsider->wait(), 4) << "matched a secure bridge without a certificate:\n"
                                   << outsider->output();
    auto member = arrivals(dir, replay, secure_env(pki, "arrivals"), "member.log");
    EXPECT_EQ(member->wait(), 0) << member->output() << bridge.output();
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->received == 150;
        },
        10s))
        << bridge.output();
    std::this_thread::sleep_for(300ms);
    EXPECT_EQ(lcm.last_estimate("restaurant")->received, 150) << "only the member's arrivals";
    EXPECT_TRUE(bridge.running());
    EXPECT_EQ(bridge.output().find("DDS Security is off"), std::string::npos) << bridge.output();
}

} // namespace
} // namespace envdesign::testing
