#!/usr/bin/env bash
# DDS Security material for Cyclone DDS's built-in plugins (authentication, access control,
# cryptography): two certificate authorities, one identity per service instance, the governance
# document and per-identity permissions generated from deploy/security/access.table, all signed
# with openssl. Keys are EC P-256 (Cyclone accepts RSA 2048 or EC P-256 only).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
table="$here/access.table"
kinds="simulator behavior courier executive planner tools operator"
ca_days=3650
identity_days=365
# Domains the governance and the permissions cover: Cyclone 0.10's governance parser refuses ids
# above 230 ("Can not parse governance file"), so 231 and 232 stay plain-only.
domain_min=0 domain_max=230

usage() {
  cat <<USAGE
Usage: deploy/security/security.sh COMMAND DIR ...

  init DIR                     make what is missing: the identity CA, the permissions CA, the
                               signed governance document
  add DIR NAME KIND [--days N] [--also PATTERN]...
                               an identity for NAME (service/instance as in a set file, or a
                               single word such as operator) with KIND's grants
                               (KIND: $kinds); --also grants publish and subscribe on topics
                               outside the catalogue (benchmarks: --also 'bench/*')
  set DIR SETFILE              init, then an identity for every process of a set file plus
                               'tools' and 'operator' (missing ones only); permissions are made
                               again where access.table is newer; then check
  renew DIR [NAME...] [--days N] [--ca]
                               new certificates (same keys) and re-signed permissions with fresh
                               dates for the NAMEs (default: every identity); --ca also re-issues
                               both CA certificates from their keys (old identities stay valid)
  check DIR [NAME...]          verify the CAs, the governance and each identity (default: all):
                               dates, key against certificate, certificate against its CA,
                               permissions signature, subject and dates; exits 1 with the reason
  uri DIR NAME [--domain N]    print the CYCLONEDDS_URI part that gives a process NAME's identity
                               (with --domain: on domain N only, other domains stay plain)
  check-table TOPICS_MD        compare access.table with the catalogue's writers/readers columns

DIR layout: identity_ca.{pem,key}, permissions_ca.{pem,key}, governance.{xml,p7s},
identities/FILE/{key.pem,cert.pem,kind,permissions.xml,permissions.p7s,cyclone.xml} where FILE is
NAME with / as - (as launch.sh names its files). Keep DIR private: it holds the CA keys.
Validity: CAs $ca_days days, identities and permissions $identity_days days (--days).
USAGE
}

die() { echo "security: $*" >&2; exit 1; }
need() { command -v "$1" >/dev/null || die "$1 not found (deploy/install-deps.sh installs it)"; }
need openssl

file_of() { echo "${1//\//-}"; }
subject_of() { echo "/O=autonomy/CN=$(file_of "$1")"; }
# The permissions document names the subject the way Cyclone compares it (RFC 2253 order).
subject_rfc() { echo "CN=$(file_of "$1"),O=autonomy"; }

check_name() {
  [[ "$1" =~ ^[A-Za-z0-9_.-]+(/[A-Za-z0-9_.-]+)?$ ]] || die "'$1' is not a NAME (service/instance or a word: letters, digits, _ . -)"
}
check_kind() {
  local k
  for k in $kinds; do [ "$k" = "$1" ] && return 0; done
  die "unknown KIND '$1' (one of: $kinds)"
}
check_days() { [[ "$1" =~ ^[0-9]+$ ]] && [ "$1" -ge 1 ] || die "--days must be a whole number of days >= 1, got '$1'"; }

# ---- The table: "topic writers readers" lines, checked with file:line.
declare -A writers=() readers=()
topics=()
read_table() {
  local n=0 line topic w r extra k who kind
  [ -f "$table" ] || die "$table not found"
  while IFS= read -r line || [ -n "$line" ]; do
    n=$((n + 1))
    line=${line%%#*}
    read -r topic w r extra <<<"$line" || true
    [ -n "$topic" ] || continue
    [ -n "$r" ] && [ -z "$extra" ] || die "$table:$n: expected TOPIC WRITERS READERS (comma-separated kinds)"
    [ -z "${writers[$topic]:-}" ] || die "$table:$n: $topic is listed twice"
    for who in ${w//,/ } ${r//,/ }; do
      k=0
      for kind in $kinds; do [ "$kind" = "$who" ] && k=1; done
      [ $k -eq 1 ] || die "$table:$n: unknown kind '$who' (one of: $kinds)"
    done
    writers[$topic]=$w readers[$topic]=$r
    topics+=("$topic")
  done <"$table"
  [ ${#topics[@]} -gt 0 ] || die "$table has no topic"
}

# grants KIND publish|subscribe: the topics KIND may write or read.
grants() {
  local kind=$1 side=$2 t list
  for t in "${topics[@]}"; do
    if [ "$side" = publish ]; then list=${writers[$t]}; else list=${readers[$t]}; fi
    [[ ",$list," == *",$kind,"* ]] && echo "$t"
  done
  return 0
}

sign() {  # sign DIR IN OUT: S/MIME signature by the permissions CA
  openssl smime -sign -in "$2" -text -out "$3" -signer "$1/permissions_ca.pem" -inkey "$1/permissions_ca.key" 2>/dev/null \
    || die "cannot sign $2 with $1/permissions_ca.pem"
}

make_ca() {  # make_ca DIR NAME TITLE
  local dir=$1 ca=$2
  [ -f "$dir/$ca.key" ] || openssl ecparam -name prime256v1 -genkey -noout -out "$dir/$ca.key" 2>/dev/null
  chmod 600 "$dir/$ca.key"
  openssl req -x509 -new -key "$dir/$ca.key" -sha256 -days "$ca_days" -subj "/O=autonomy/CN=autonomy $3" \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,digitalSignature,keyCertSign,cRLSign" \
    -out "$dir/$ca.pem" 2>/dev/null || die "cannot make $dir/$ca.pem"
}

governance_xml() {
  cat <<XML
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>ENCRYPT</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
XML
}

cmd_init() {
  local dir=$1
  mkdir -p "$dir/identities"
  chmod 700 "$dir"
  [ -f "$dir/identity_ca.pem" ] || { make_ca "$dir" identity_ca "identity CA"; echo "security: made $dir/identity_ca.pem"; }
  [ -f "$dir/permissions_ca.pem" ] || { make_ca "$dir" permissions_ca "permissions CA"; echo "security: made $dir/permissions_ca.pem"; }
  if [ ! -f "$dir/governance.p7s" ]; then
    governance_xml >"$dir/governance.xml"
    sign "$dir" "$dir/governance.xml" "$dir/governance.p7s"
    echo "security: made $dir/governance.p7s"
  fi
}

permissions_xml() {  # permissions_xml NAME KIND NOT_BEFORE NOT_AFTER EXTRA_TOPICS
  local t
  cat <<XML
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$(file_of "$1")">
      <subject_name>$(subject_rfc "$1")</subject_name>
      <validity><not_before>$3</not_before><not_after>$4</not_after></validity>
XML
  # One allow rule per side: Cyclone 0.10 wants allow rules with default DENY (a deny rule can
  # block creating the topic at all, cyclonedds#2267).
  local pub sub
  pub=$(grants "$2" publish) sub=$(grants "$2" subscribe)
  if [ -n "$5" ]; then pub+=$'\n'"$5"; sub+=$'\n'"$5"; fi
  if [ -n "$pub" ] || [ -n "$sub" ]; then
    echo "      <allow_rule>"
    echo "        <domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>"
    if [ -n "$pub" ]; then
      echo "        <publish><topics>"
      while read -r t; do [ -z "$t" ] || echo "          <topic>$t</topic>"; done <<<"$pub"
      echo "        </topics></publish>"
    fi
    if [ -n "$sub" ]; then
      echo "        <subscribe><topics>"
      while read -r t; do [ -z "$t" ] || echo "          <topic>$t</topic>"; done <<<"$sub"
      echo "        </topics></subscribe>"
    fi
    echo "      </allow_rule>"
  fi
  cat <<XML
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
XML
}

cyclone_xml() {  # cyclone_xml DIR FILE [DOMAIN]: the Security section of one identity
  local dir=$1 id="$1/identities/$2" domain=${3:-any}
  cat <<XML
<?xml version="1.0" encoding="UTF-8"?>
<!-- Generated by deploy/security/security.sh: identity $2. Add it to CYCLONEDDS_URI after the
     network profile: CYCLONEDDS_URI=file://.../loopback.xml,file://$id/cyclone.xml -->
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain id="$domain">
    <Security>
      <Authentication>
        <IdentityCertificate>file:$id/cert.pem</IdentityCertificate>
        <IdentityCA>file:$dir/identity_ca.pem</IdentityCA>
        <PrivateKey>file:$id/key.pem</PrivateKey>
      </Authentication>
      <AccessControl>
        <Governance>file:$dir/governance.p7s</Governance>
        <PermissionsCA>file:$dir/permissions_ca.pem</PermissionsCA>
        <Permissions>file:$id/permissions.p7s</Permissions>
      </AccessControl>
    </Security>
  </Domain>
</CycloneDDS>
XML
}

# issue DIR NAME KIND DAYS: certificate (key kept if present), permissions, Cyclone section.
issue() {
  local dir=$1 name=$2 kind=$3 days=$4 file id serial
  file=$(file_of "$name")
  id="$dir/identities/$file"
  mkdir -p "$id"
  [ -f "$id/key.pem" ] || openssl ecparam -name prime256v1 -genkey -noout -out "$id/key.pem" 2>/dev/null
  chmod 600 "$id/key.pem"
  serial=0x$(openssl rand -hex 16)
  openssl req -new -key "$id/key.pem" -subj "$(subject_of "$name")" 2>/dev/null \
    | openssl x509 -req -CA "$dir/identity_ca.pem" -CAkey "$dir/identity_ca.key" -set_serial "$serial" \
        -days "$days" -sha256 -out "$id/cert.pem" 2>/dev/null || die "cannot issue the certificate of $name"
  echo "$kind" >"$id/kind"
  echo "$days" >"$id/days"
  make_permissions "$dir" "$name"
  cyclone_xml "$dir" "$file" >"$id/cyclone.xml"
}

# make_permissions DIR NAME: from the table, valid as long as the certificate.
make_permissions() {
  local dir=$1 name=$2 id kind from to
  id="$dir/identities/$(file_of "$name")"
  kind=$(cat "$id/kind")
  from=$(date -u -d "$(openssl x509 -in "$id/cert.pem" -noout -startdate | cut -d= -f2)" +%Y-%m-%dT%H:%M:%S)
  to=$(date -u -d "$(openssl x509 -in "$id/cert.pem" -noout -enddate | cut -d= -f2)" +%Y-%m-%dT%H:%M:%S)
  permissions_xml "$name" "$kind" "$from" "$to" "$(cat "$id/also" 2>/dev/null || true)" >"$id/permissions.xml"
  sign "$dir" "$id/permissions.xml" "$id/permissions.p7s"
}

need_init() {
  [ -f "$1/identity_ca.pem" ] && [ -f "$1/permissions_ca.pem" ] && [ -f "$1/governance.p7s" ] \
    || die "$1 has no certificate authorities: run deploy/security/security.sh init $1"
}

cmd_add() {
  local dir=$1 name=$2 kind=$3 days=$identity_days also=""
  shift 3
  while [ $# -gt 0 ]; do
    case $1 in
      --days) [ $# -ge 2 ] || die "--days needs a value"; days=$2; check_days "$days"; shift 2 ;;
      --also) [ $# -ge 2 ] || die "--also needs a topic pattern"
        [[ "$2" =~ ^[A-Za-z0-9_/*?.-]+$ ]] || die "--also: '$2' is not a topic name or pattern"
        also+="$2"$'\n'; shift 2 ;;
      *) die "add: unknown argument '$1'" ;;
    esac
  done
  check_name "$name"; check_kind "$kind"; need_init "$dir"; read_table
  mkdir -p "$dir/identities/$(file_of "$name")"
  printf '%s' "$also" >"$dir/identities/$(file_of "$name")/also"
  issue "$dir" "$name" "$kind" "$days"
  echo "security: identity $name ($kind) in $dir/identities/$(file_of "$name"), valid $days days"
}

all_names() {  # every identity of DIR (as file names)
  local d
  for d in "$1"/identities/*/; do [ -f "$d/cert.pem" ] && basename "$d"; done
  return 0
}

cmd_set() {
  local dir=$1 set_file=$2 line words name kind n=0 made=0
  [ -f "$set_file" ] || die "set file $set_file not found"
  cmd_init "$dir"; read_table
  local names=(tools operator)
  while IFS= read -r line || [ -n "$line" ]; do
    n=$((n + 1))
    line=${line%%#*}
    read -r -a words <<<"$line" || true
    [ ${#words[@]} -gt 0 ] || continue
    name=${words[0]}
    [[ "$name" == */* ]] || name="$name/main"
    names+=("$name")
  done <"$set_file"
  for name in "${names[@]}"; do
    check_name "$name"
    kind=${name%%/*}
    check_kind "$kind"
    local id="$dir/identities/$(file_of "$name")"
    if [ ! -f "$id/cert.pem" ]; then
      issue "$dir" "$name" "$kind" "$identity_days"
      echo "security: made identity $name ($kind)"
      made=1
    elif [ "$table" -nt "$id/permissions.p7s" ]; then
      make_permissions "$dir" "$name"
      echo "security: permissions of $name made again (access.table changed)"
    fi
  done
  local files=()
  for name in "${names[@]}"; do files+=("$(file_of "$name")"); done
  cmd_check "$dir" "${files[@]}"
}

# expiry FILE WHAT: clear errors for dates.
check_dates() {  # check_dates CERT WHAT RENEW_COMMAND
  local cert=$1 what=$2 end start
  end=$(openssl x509 -in "$cert" -noout -enddate | cut -d= -f2)
  start=$(openssl x509 -in "$cert" -noout -startdate | cut -d= -f2)
  if ! openssl x509 -in "$cert" -noout -checkend 0 >/dev/null; then
    fail "$what $cert expired on $end: renew it ($3)"
    return
  fi
  [ "$(date -u -d "$start" +%s)" -le "$(date -u +%s)" ] || fail "$what $cert is not valid before $start (check this host's clock)"
  if ! openssl x509 -in "$cert" -noout -checkend $((30 * 86400)) >/dev/null; then
    echo "security: warning: $what $cert expires on $end (within 30 days): renew it soon" >&2
  fi
}

failures=0
fail() { echo "security: $*" >&2; failures=$((failures + 1)); }

pubkey_of_cert() { openssl x509 -in "$1" -noout -pubkey 2>/dev/null; }
pubkey_of_key() { openssl pkey -in "$1" -pubout 2>/dev/null; }

check_identity() {  # check_identity DIR FILE
  local dir=$1 file=$2 id="$1/identities/$2" subject perm_subject nb na now
  [ -d "$id" ] || { fail "no identity $file in $dir/identities (make it: security.sh add $dir NAME KIND)"; return; }
  for f in key.pem cert.pem permissions.p7s cyclone.xml; do
    [ -f "$id/$f" ] || { fail "identity $file: $id/$f is missing"; return; }
  done
  check_dates "$id/cert.pem" "the certificate of $file" "deploy/security/security.sh renew $dir $file"
  [ "$(pubkey_of_cert "$id/cert.pem")" = "$(pubkey_of_key "$id/key.pem")" ] \
    || fail "identity $file: $id/cert.pem does not match its key $id/key.pem (a certificate issued for another key)"
  # -no_check_time: an expired certificate is reported above as expired, not as foreign.
  openssl verify -no_check_time -CAfile "$dir/identity_ca.pem" "$id/cert.pem" >/dev/null 2>&1 \
    || fail "identity $file: $id/cert.pem is not signed by this identity CA ($dir/identity_ca.pem)"
  if ! openssl smime -verify -in "$id/permissions.p7s" -CAfile "$dir/permissions_ca.pem" -out "$id/.permissions.check" >/dev/null 2>&1; then
    fail "identity $file: $id/permissions.p7s is not signed by this permissions CA ($dir/permissions_ca.pem), or was changed after signing"
  else
    subject=$(subject_rfc "$file")
    perm_subject=$(sed -n 's:.*<subject_name>\(.*\)</subject_name>.*:\1:p' "$id/.permissions.check")
    [ "$perm_subject" = "$subject" ] || fail "identity $file: its permissions are for '$perm_subject', its certificate is '$subject'"
    nb=$(sed -n 's:.*<not_before>\(.*\)</not_before>.*:\1:p' "$id/.permissions.check")
    na=$(sed -n 's:.*<not_after>\(.*\)</not_after>.*:\1:p' "$id/.permissions.check")
    now=$(date -u +%Y-%m-%dT%H:%M:%S)
    [[ "$now" < "$na" ]] || fail "identity $file: its permissions expired on $na: renew them (security.sh renew $dir $file)"
    [[ "$nb" < "$now" || "$nb" = "$now" ]] || fail "identity $file: its permissions are not valid before $nb"
  fi
  rm -f "$id/.permissions.check"
}

cmd_check() {
  local dir=$1; shift
  need_init "$dir"
  failures=0
  check_dates "$dir/identity_ca.pem" "the identity CA" "deploy/security/security.sh renew $dir --ca"
  check_dates "$dir/permissions_ca.pem" "the permissions CA" "deploy/security/security.sh renew $dir --ca"
  openssl smime -verify -in "$dir/governance.p7s" -CAfile "$dir/permissions_ca.pem" -out /dev/null >/dev/null 2>&1 \
    || fail "$dir/governance.p7s is not signed by this permissions CA ($dir/permissions_ca.pem), or was changed after signing"
  local names=("$@")
  [ ${#names[@]} -gt 0 ] || mapfile -t names < <(all_names "$dir")
  local name
  for name in "${names[@]}"; do check_identity "$dir" "$(file_of "$name")"; done
  [ $failures -eq 0 ] || exit 1
  echo "security: $dir: CAs, governance and ${#names[@]} identities valid"
}

cmd_renew() {
  local dir=$1 days="" ca=0 names=() name file
  shift
  while [ $# -gt 0 ]; do
    case $1 in
      --days) [ $# -ge 2 ] || die "--days needs a value"; days=$2; check_days "$days"; shift 2 ;;
      --ca) ca=1; shift ;;
      -*) die "renew: unknown option '$1'" ;;
      *) names+=("$1"); shift ;;
    esac
  done
  need_init "$dir"; read_table
  if [ $ca -eq 1 ]; then
    make_ca "$dir" identity_ca "identity CA"
    make_ca "$dir" permissions_ca "permissions CA"
    governance_xml >"$dir/governance.xml"
    sign "$dir" "$dir/governance.xml" "$dir/governance.p7s"
    echo "security: renewed both CA certificates (same keys) and the governance"
  fi
  [ ${#names[@]} -gt 0 ] || mapfile -t names < <(all_names "$dir")
  for name in "${names[@]}"; do
    file=$(file_of "$name")
    [ -f "$dir/identities/$file/kind" ] || die "renew: no identity $file in $dir/identities"
    issue "$dir" "$file" "$(cat "$dir/identities/$file/kind")" "${days:-$(cat "$dir/identities/$file/days" 2>/dev/null || echo $identity_days)}"
    echo "security: renewed $file until $(openssl x509 -in "$dir/identities/$file/cert.pem" -noout -enddate | cut -d= -f2)"
  done
}

cmd_uri() {
  local dir=$1 file
  file=$(file_of "$2")
  [ -f "$dir/identities/$file/cyclone.xml" ] || die "no identity $2 in $dir/identities (make it: security.sh add $dir $2 KIND)"
  if [ $# -eq 4 ] && [ "$3" = --domain ]; then
    [[ "$4" =~ ^[0-9]+$ ]] && [ "$4" -le $domain_max ] || die "--domain must be 0..$domain_max, got '$4'"
    cyclone_xml "$(cd "$dir" && pwd)" "$file" "$4" >"$dir/identities/$file/cyclone-domain-$4.xml"
    echo "file://$(cd "$dir" && pwd)/identities/$file/cyclone-domain-$4.xml"
    return
  fi
  [ $# -eq 2 ] || die "usage: uri DIR NAME [--domain N]"
  echo "file://$(cd "$dir" && pwd)/identities/$file/cyclone.xml"
}

# check-table TOPICS_MD: the catalogue's writers and readers columns start with the kinds in bold
# (**simulator**, **tools**, ...); they must be the table's, topic by topic, and both must list
# the same topics (the table may add topics that docs/topics.md names outside the catalogue).
cmd_check_table() {
  local md=$1
  [ -f "$md" ] || die "$md not found"
  read_table  # the table's own mistakes, with file:line
  # One awk pass (a fork per topic made this take seconds on a loaded machine).
  awk -v kinds=" $kinds " -v table="$table" '
    function norm(list,   n, a, i, j, t, out) {
      n = split(list, a, ",")
      for (i = 2; i <= n; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
      out = ""
      for (i = 1; i <= n; i++) if (a[i] != "") out = out (out == "" ? "" : ",") a[i]
      return out
    }
    function bold(cell,   out, w) {
      out = ""
      while (match(cell, /\*\*[a-z]+\*\*/)) {
        w = substr(cell, RSTART + 2, RLENGTH - 4)
        if (index(kinds, " " w " ")) out = out (out == "" ? "" : ",") w
        cell = substr(cell, RSTART + RLENGTH)
      }
      return norm(out)
    }
    FNR == NR {
      sub(/#.*/, "")
      if (NF == 3) { W[$1] = norm($2); R[$1] = norm($3); order[++n] = $1 }
      next
    }
    { text = text "\n" $0 }
    /^\| `autonomy\// {
      split($0, c, "|")
      topic = c[2]; gsub(/[ `]/, "", topic)
      seen[topic] = 1
      if (!(topic in W)) { print FILENAME ":" FNR ": " topic " is in the catalogue but not in " table; errors++; next }
      w = bold(c[6]); r = bold(c[7])
      if (w != W[topic]) { print FILENAME ":" FNR ": " topic " writers: the catalogue says '\''" (w == "" ? "none in bold" : w) "'\'', " table " says '\''" W[topic] "'\''"; errors++ }
      if (r != R[topic]) { print FILENAME ":" FNR ": " topic " readers: the catalogue says '\''" (r == "" ? "none in bold" : r) "'\'', " table " says '\''" R[topic] "'\''"; errors++ }
    }
    END {
      for (i = 1; i <= n; i++)
        if (!(order[i] in seen) && index(text, "`" order[i] "`") == 0) { print table ": " order[i] " is not in " FILENAME; errors++ }
      if (errors) { print table " and " FILENAME " disagree (" errors " differences)"; exit 1 }
      print table " agrees with " FILENAME " (" n " topics)"
    }' "$table" "$md" | sed 's/^/security: /' >&2
  [ "${PIPESTATUS[0]}" -eq 0 ] || exit 1
}

[ $# -ge 1 ] || { usage >&2; exit 2; }
command=$1; shift
case $command in
  -h|--help|help) usage ;;
  init) [ $# -eq 1 ] || die "usage: init DIR"; cmd_init "$1" ;;
  add) [ $# -ge 3 ] || die "usage: add DIR NAME KIND [--days N]"; cmd_add "$@" ;;
  set) [ $# -eq 2 ] || die "usage: set DIR SETFILE"; cmd_set "$@" ;;
  renew) [ $# -ge 1 ] || die "usage: renew DIR [NAME...] [--days N] [--ca]"; cmd_renew "$@" ;;
  check) [ $# -ge 1 ] || die "usage: check DIR [NAME...]"; cmd_check "$@" ;;
  uri) [ $# -eq 2 ] || [ $# -eq 4 ] || die "usage: uri DIR NAME [--domain N]"; cmd_uri "$@" ;;
  check-table) [ $# -eq 1 ] || die "usage: check-table TOPICS_MD"; cmd_check_table "$1" ;;
  *) echo "security: unknown command '$command'" >&2; usage >&2; exit 2 ;;
esac
