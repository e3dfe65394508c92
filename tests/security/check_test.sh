#!/usr/bin/env bash
# security.sh check and renew on real openssl material: an identity whose certificate has expired
# is refused with its end date and the renew command; renew gives it a fresh year on the same key
# and the check passes again; a permissions document changed by hand is refused until renewed.
set -euo pipefail
repo=${1:?usage: check_test.sh REPO}
s="$repo/deploy/security/security.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

bash "$s" init "$dir/keys" >/dev/null
bash "$s" add "$dir/keys" behavior/r1 behavior >/dev/null
bash "$s" check "$dir/keys" >/dev/null 2>&1 || fail "a fresh identity is refused"
id="$dir/keys/identities/behavior-r1"
key_before=$(openssl pkey -in "$id/key.pem" -pubout)

# A certificate valid for 0 days ends the second it is made.
openssl req -new -key "$id/key.pem" -subj "/O=autonomy/CN=behavior-r1" 2>/dev/null \
  | openssl x509 -req -CA "$dir/keys/identity_ca.pem" -CAkey "$dir/keys/identity_ca.key" -set_serial 7 -days 0 \
      -out "$id/cert.pem" 2>/dev/null
if bash "$s" check "$dir/keys" behavior/r1 2>"$dir/err"; then fail "an expired certificate passed the check"; fi
grep -q "the certificate of behavior-r1 .* expired on .*: renew it (deploy/security/security.sh renew $dir/keys behavior-r1)" "$dir/err" \
  || { cat "$dir/err" >&2; fail "the expiry is not reported with the renew command"; }
grep -q "not signed by this identity CA" "$dir/err" && { cat "$dir/err" >&2; fail "an expired certificate was called foreign"; }

bash "$s" renew "$dir/keys" behavior/r1 >/dev/null
bash "$s" check "$dir/keys" behavior/r1 >/dev/null 2>&1 || fail "renewed identity refused"
[ "$(openssl pkey -in "$id/key.pem" -pubout)" = "$key_before" ] || fail "renew changed the key"
openssl x509 -in "$id/cert.pem" -noout -checkend $((300 * 86400)) >/dev/null || fail "renewed certificate ends within 300 days"

# One granted topic changed inside the signed permissions.
sed -i 's|<topic>autonomy/robot/cmd_vel</topic>|<topic>autonomy/clock</topic>|' "$id/permissions.p7s"
if bash "$s" check "$dir/keys" behavior/r1 2>"$dir/err2"; then fail "tampered permissions passed the check"; fi
grep -q "permissions.p7s is not signed by this permissions CA" "$dir/err2" || { cat "$dir/err2" >&2; fail "tampering not named"; }
bash "$s" renew "$dir/keys" behavior/r1 >/dev/null
bash "$s" check "$dir/keys" behavior/r1 >/dev/null 2>&1 || fail "renew did not restore the permissions"
echo "check_test: ok"
