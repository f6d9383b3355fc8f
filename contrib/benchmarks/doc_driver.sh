# Sourced by the benchmark drivers that write a table into doc/, after setting top:
#   doc_driver_arguments NAME "$@"  reads the driver's arguments ([--update-doc] [output
#                                   directory]), sets build_dir, update_doc (0 or 1) and out
#                                   (default output/NAME), creates out, and stops with a message
#                                   if /usr/bin/time is missing;
#   write_between_markers DOC MARKER TABLE  puts the file TABLE into DOC between the lines
#                                   "<!-- MARKER: begin -->" and "<!-- MARKER: end -->".

doc_driver_arguments() {
  local name="$1"
  shift
  build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
  update_doc=0
  out=""
  for argument in "$@"; do
    case "${argument}" in
      --update-doc) update_doc=1 ;;
      *) out="${argument}" ;;
    esac
  done
  out="${out:-${top}/output/${name}}"
  mkdir -p "${out}"
  [[ -x /usr/bin/time ]] || { echo "${name}.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 1; }
}

write_between_markers() {
  /usr/bin/python3 - "$1" "$2" "$3" <<'PYTHON'
import sys
doc, marker, table = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
text = open(doc).read()
begin, end = "<!-- %s: begin -->" % marker, "<!-- %s: end -->" % marker
head, rest = text.split(begin)
_, tail = rest.split(end)
open(doc, "w").write(head + begin + "\n" + table + end + tail)
PYTHON
  echo "$(basename "$0"): table written into $1"
}
