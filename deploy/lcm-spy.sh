#!/usr/bin/env bash
# deploy/lcm-spy.sh [--lcm-url URL] [--check SECONDS]
#
# lcm-spy with envdesign's types, so that every ENVDESIGN_ channel is decoded. Debian's
# /usr/bin/lcm-spy passes -Xincgc, which Java 17 refuses ("Could not create the Java Virtual
# Machine"), so this runs lcm.spy.Spy directly. Needs liblcm-java and libjchart2d-java; the
# types jar is build/lcmtypes/envdesign_lcmtypes.jar, or $ENVDESIGN_LCM_JAR, or the installed
# one (share/java/envdesign_lcmtypes.jar).
#
# On an authenticated bus (deploy/LAN.md "Authentication") lcm-spy needs no key: messages are
# the LCM encoding followed by a trailer, and LCM's Java decoders ignore bytes after a message.
# It cannot verify them either: what it shows may be forged.
#
# --check SECONDS: no window for you. Runs lcm-spy under Xvfb for SECONDS on URL and checks
# from its channel table that every ENVDESIGN_ channel heard was decoded, and that all of
# $ENVDESIGN_SPY_CHANNELS (default: all ten) were heard. Exit 0 when so.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
url=${LCM_DEFAULT_URL:-udpm://239.255.76.67:7667?ttl=0}
check=""
while [ $# -gt 0 ]; do
    case $1 in
        --lcm-url) url=$2; shift 2 ;;
        --check) check=$2; shift 2 ;;
        *) echo "lcm-spy.sh: unknown option $1" >&2; exit 2 ;;
    esac
done

jar=${ENVDESIGN_LCM_JAR:-}
for candidate in "$here/../build/lcmtypes/envdesign_lcmtypes.jar" \
                 "$here/../share/java/envdesign_lcmtypes.jar" \
                 /usr/local/share/java/envdesign_lcmtypes.jar; do
    [ -z "$jar" ] && [ -f "$candidate" ] && jar=$candidate
done
[ -n "$jar" ] || { echo "lcm-spy.sh: envdesign_lcmtypes.jar not found (build first)" >&2; exit 1; }
lcm_jar=$(pkg-config --variable=classpath lcm-java 2>/dev/null || echo /usr/share/java/lcm.jar)
classpath="$lcm_jar:/usr/share/java/jchart2d.jar:$jar"
java_flags=(-Djava.net.preferIPv4Stack=true -Xmx256m)

if [ -z "$check" ]; then
    exec java "${java_flags[@]}" -cp "$classpath" lcm.spy.Spy --lcm-url="$url"
fi

channels=${ENVDESIGN_SPY_CHANNELS:-ENVDESIGN_REQUEST ENVDESIGN_CANCEL ENVDESIGN_PROGRESS ENVDESIGN_RESULT ENVDESIGN_SPEC ENVDESIGN_JOB ENVDESIGN_SPEC_NEED ENVDESIGN_EVALUATION ENVDESIGN_HEARTBEAT ENVDESIGN_STATUS}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
javac -d "$work" -cp "$classpath" "$here/lcm-spy/LcmCheck.java"
# shellcheck disable=SC2086
xvfb-run -a java "${java_flags[@]}" -cp "$classpath:$work" LcmCheck spy "$url" "$check" $channels
