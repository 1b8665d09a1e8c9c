#!/bin/sh
# Generates the man pages of the poinsot tool from its own --help, one page for the tool and one for every
# sub-command (poinsot-inertia-box.1.gz for `poinsot inertia box`), with help2man. Run by the build
# (apps/poinsot/CMakeLists.txt) whenever the tool is relinked; the list of sub-commands comes from the tool
# itself (`poinsot completion commands`), so a new sub-command gets its page without an edit here.
# Usage: poinsot-manpages.sh POINSOT_EXE HELP2MAN OUT_DIR
# OUT_DIR is replaced whole (built beside it, then renamed), so a removed sub-command leaves no stale page.
set -eu
exe=$1
help2man=$2
out=$3

version=$("$exe" --version | sed 's/^poinsot //')
work="${out:?}.tmp"
rm -rf "$work"
mkdir -p "$work/bin"
"$exe" completion commands >"$work/commands"

# help2man documents one program: give each sub-command a wrapper named poinsot-a-b that runs `poinsot a b`.
page() {  # page NAME "ARGS" "DESCRIPTION" SEE_ALSO
  printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$exe" "$2" >"$work/bin/$1"
  chmod +x "$work/bin/$1"
  printf '[SEE ALSO]\n%s\n' "$4" >"$work/$1.h2m"
  "$help2man" --no-info --no-discard-stderr --version-string="$version" --name="$3" \
    --include="$work/$1.h2m" --output="$work/$1.1" "$work/bin/$1"
  gzip -9n "$work/$1.1"
}

see_also=""
tab=$(printf '\t')
while IFS="$tab" read -r path description; do
  see_also="$see_also.BR poinsot-$(echo "$path" | tr ' ' '-') (1)
"
done <"$work/commands"
page poinsot "" "rotation of rigid bodies: inertia, Euler's equations, Lagrange multipliers" "$see_also"
while IFS="$tab" read -r path description; do
  page "poinsot-$(echo "$path" | tr ' ' '-')" "$path" "$description" ".BR poinsot (1)"
done <"$work/commands"

rm -rf "${work:?}/bin" "$work"/*.h2m "$work/commands"
rm -rf "$out"
mv "$work" "$out"
echo "man pages: $(find "$out" -name "*.1.gz" | wc -l) written to $out"
