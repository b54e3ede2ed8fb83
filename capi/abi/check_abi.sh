#!/bin/sh
# The ABI gate: libabigail's abidiff between the committed v1 baseline
# (capi/abi/eoir_v1.abi) and the library of this build, over the types of
# the public header only. Additions (new functions, new table entries at the
# end) are compatible; a removed or changed function, a moved struct field or
# a changed type fails; members appended at the end of an eoir_* struct are
# compatible (structs start with struct_size and only grow at the end:
# appended_members.suppr). abidiff's exit status is a bit field (1 error,
# 2 usage, 4 ABI change, 8 incompatible change) that counts a moved member
# as a mere "change", so the verdict is read from its summary: any Removed
# or Changed function or variable fails, Added ones pass.
#
# Before trusting the verdict, the script shows on this very library that a
# removed function and a moved struct member fail and an added function
# passes (so that a broken abidiff cannot pass everything).
#
# usage: check_abi.sh LIBRARY BASELINE.abi INCLUDE_DIR WORK_DIR [PYTHON]
# To renew the baseline after a deliberate major-version change:
#   abidw --exported-interfaces-only --drop-private-types --headers-dir capi/include \
#         --no-corpus-path --no-comp-dir-path --short-locs --out-file capi/abi/eoir_v1.abi build/lib/libeoir.so.1
set -u
lib=$1; baseline=$2; inc=$3; work=$4; py=${5:-/usr/bin/python3}
suppr=$(dirname "$0")/appended_members.suppr
mkdir -p "$work"
fail() { echo "check_abi: FAIL: $*" >&2; exit 1; }
abidw --exported-interfaces-only --drop-private-types --headers-dir "$inc" --no-corpus-path --no-comp-dir-path \
      --short-locs --out-file "$work/current.abi" "$lib" || fail "abidw $lib"

# Self-check: drop eoir_truth_get (its ELF symbol and declaration) from a copy.
drop() {  # drop FILE_IN FILE_OUT: the same ABI without eoir_truth_get
  awk '
    /<elf-symbol name=.eoir_truth_get./ { next }
    /<function-decl name=.eoir_truth_get./ { skip = 1 }
    skip { if (/<\/function-decl>/) { skip = 0 } ; next }
    { print }' "$1" > "$2"
}
drop "$work/current.abi" "$work/removed.abi"
grep -q "eoir_truth_get" "$work/removed.abi" && fail "self-check: could not drop eoir_truth_get"
# verdict FILE: "ok" unless abidiff's summary counts a removed or changed
# function or variable.
verdict() {
  if grep -E "^(Functions|Variables) changes summary:" "$1" | grep -qvE ": 0 Removed, 0 Changed"; then
    echo incompatible
  else
    echo ok
  fi
}
compare() {  # compare OLD NEW OUT
  abidiff --suppressions "$suppr" --headers-dir1 "$inc" --headers-dir2 "$inc" "$1" "$2" > "$3" 2>&1
  rc=$?
  [ $((rc & 3)) -eq 0 ] || { cat "$3"; fail "abidiff could not compare $1 and $2 (exit $rc)"; }
}
compare "$work/current.abi" "$work/removed.abi" "$work/removed.txt"
[ "$(verdict "$work/removed.txt")" = incompatible ] || { cat "$work/removed.txt"; fail "self-check: a removed function passes"; }
compare "$work/removed.abi" "$work/current.abi" "$work/added.txt"
[ "$(verdict "$work/added.txt")" = ok ] || { cat "$work/added.txt"; fail "self-check: an added function fails"; }
# a member inserted into eoir_image_info before `unit`: the members after it
# move by 64 bits and the struct grows
"$py" - "$work/current.abi" "$work/moved.abi" <<'PY' || fail "self-check: could not insert a member"
import copy, sys, xml.etree.ElementTree as ET
tree = ET.parse(sys.argv[1])
done = 0
for c in tree.iter("class-decl"):
    if c.get("name") != "eoir_image_info" or c.get("is-declaration-only") == "yes":
        continue
    members = c.findall("data-member")
    names = [m.find("var-decl").get("name") for m in members]
    at = names.index("unit")
    new = copy.deepcopy(members[names.index("kind")])
    new.find("var-decl").set("name", "inserted")
    new.set("layout-offset-in-bits", members[at].get("layout-offset-in-bits"))
    for m in members[at:]:
        m.set("layout-offset-in-bits", str(int(m.get("layout-offset-in-bits")) + 64))
    c.insert(list(c).index(members[at]), new)
    c.set("size-in-bits", str(int(c.get("size-in-bits")) + 64))
    done += 1
assert done >= 1, "eoir_image_info not found"
tree.write(sys.argv[2])
PY
compare "$work/current.abi" "$work/moved.abi" "$work/moved.txt"
[ "$(verdict "$work/moved.txt")" = incompatible ] || { cat "$work/moved.txt"; fail "self-check: a moved member passes"; }
echo "check_abi: self-check: removal and a moved member fail, an addition passes"

compare "$baseline" "$work/current.abi" "$work/diff.txt"
cat "$work/diff.txt"
[ "$(verdict "$work/diff.txt")" = ok ] || fail "incompatible ABI change against $baseline"
echo "check_abi: ok: compatible with the v1 baseline"
