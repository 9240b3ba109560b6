#!/usr/bin/env bash
# deploy/dds-security/make-pki.sh DIR [NAME...]
#
# The files Cyclone DDS Security (authentication, access control, encryption) needs for the
# task-arrival topic, made with openssl: one CA (identity and permissions), a certificate and
# key per participant NAME (default: bridge arrivals), the governance document and the
# permissions document, both signed by the CA. DIR/ca.key signs new participants later: keep
# it off the machines. Use the result with deploy/dds-security/cyclonedds-secure.xml
# (deploy/LAN.md "DDS").
set -euo pipefail

dir=${1:?usage: make-pki.sh DIR [NAME...]}
shift
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(bridge arrivals)
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$dir"
cd "$dir"
umask 077
days=3650
ec=(-newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes)

if [ ! -f ca.pem ]; then
    openssl req -x509 "${ec[@]}" -keyout ca.key -out ca.pem -days "$days" \
        -subj "/O=envdesign/CN=envdesign DDS CA" 2>/dev/null
fi
for name in "${names[@]}"; do
    [ -f "$name.pem" ] && continue
    openssl req "${ec[@]}" -keyout "$name.key" -out "$name.csr" \
        -subj "/O=envdesign/CN=$name" 2>/dev/null
    openssl x509 -req -in "$name.csr" -CA ca.pem -CAkey ca.key -CAcreateserial \
        -out "$name.pem" -days "$days" 2>/dev/null
    rm -f "$name.csr"
done

# Every participant with a certificate of this CA may publish and subscribe arrivals in every
# domain; the governance makes Cyclone refuse participants without one and encrypt the data.
not_before=$(date -u +%Y-%m-%dT%H:%M:%S)
not_after=$(date -u -d "+$days days" +%Y-%m-%dT%H:%M:%S)
{
    echo '<?xml version="1.0" encoding="UTF-8"?>'
    echo '<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"'
    echo '     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">'
    echo '  <permissions>'
    for name in "${names[@]}"; do
        cat <<GRANT
    <grant name="$name">
      <subject_name>CN=$name,O=envdesign</subject_name>
      <validity><not_before>$not_before</not_before><not_after>$not_after</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
        <publish><topics><topic>*</topic></topics><partitions><partition>*</partition></partitions></publish>
        <subscribe><topics><topic>*</topic></topics><partitions><partition>*</partition></partitions></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
GRANT
    done
    echo '  </permissions>'
    echo '</dds>'
} >permissions.xml
cp "$here/governance.xml" governance.xml
openssl smime -sign -in governance.xml -text -out governance.p7s -signer ca.pem -inkey ca.key
openssl smime -sign -in permissions.xml -text -out permissions.p7s -signer ca.pem -inkey ca.key
echo "make-pki.sh: CA and ${names[*]} in $dir"
