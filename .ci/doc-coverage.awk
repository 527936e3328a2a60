# Documented-symbol coverage of the public API from Doxygen's XML, produced
# with EXTRACT_ALL=YES so that undocumented entities are listed too: every
# public class or struct, member (function, typedef, enum, variable), macro
# and enumerator counts once (by id), and is documented when its brief or
# detailed description holds a paragraph.
#   awk -f .ci/doc-coverage.awk XML_DIR/*.xml
# Prints "documented D of N" and each undocumented symbol; exits 1 if any.
function open_entity(id, kind) {
  depth++; ids[depth] = id; kinds[depth] = kind; names[depth] = ""
  if(!(id in seen)) { seen[id] = 1; order[++n] = id; kind_of[id] = kind }
}
function close_entity() { if(!(ids[depth] in label)) label[ids[depth]] = names[depth]; depth-- }
function attr(line, key,   m) {
  if(match(line, key "=\"[^\"]*\"")) { m = substr(line, RSTART + length(key) + 2, RLENGTH - length(key) - 3); return m }
  return ""
}
FNR == 1 { depth = 0; in_desc = 0 }
# A private or protected nested class is not API, nor are its members.
/<compounddef / {
  k = attr($0, "kind"); p = attr($0, "prot")
  hidden = (p == "private" || p == "protected")
  if((k == "class" || k == "struct") && !hidden) open_entity(attr($0, "id"), k)
  else { depth++; ids[depth] = ""; }
  next
}
/<\/compounddef>/ { if(ids[depth] != "") close_entity(); else depth--; hidden = 0; next }
/<memberdef / {
  k = attr($0, "kind")
  if(!hidden && attr($0, "prot") == "public" && k != "friend") open_entity(attr($0, "id"), k)
  else { depth++; ids[depth] = "" }
  next
}
/<\/memberdef>/ { if(ids[depth] != "") close_entity(); else depth--; next }
/<enumvalue / { if(!hidden && attr($0, "prot") == "public") open_entity(attr($0, "id"), "enumvalue"); else { depth++; ids[depth] = "" }; next }
/<\/enumvalue>/ { if(ids[depth] != "") close_entity(); else depth--; next }
/<(compoundname|name)>/ {
  if(depth > 0 && ids[depth] != "" && names[depth] == "") {
    s = $0; sub(/.*<(compoundname|name)>/, "", s); sub(/<\/(compoundname|name)>.*/, "", s); names[depth] = s
  }
}
/<(briefdescription|detaileddescription)>/ { in_desc = 1 }
/<para>/ { if(in_desc && depth > 0 && ids[depth] != "") documented[ids[depth]] = 1 }
/<\/(briefdescription|detaileddescription)>/ { in_desc = 0 }
END {
  undocumented = 0
  for(i = 1; i <= n; ++i) if(!(order[i] in documented)) {
    ++undocumented
    printf("undocumented %s: %s\n", kind_of[order[i]], label[order[i]])
  }
  printf("documented %d of %d public symbols (classes, members, macros, enumerators)\n", n - undocumented, n)
  exit undocumented > 0
}
