// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Library-internal text helpers.

#ifndef BRDFBAKE_SRC_BASE_TEXT_H_
#define BRDFBAKE_SRC_BASE_TEXT_H_

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace brdfbake {

// ASCII lower case (file extensions).
inline std::string Lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A number in C's "%.9g": every float exactly, short where it can be.
inline std::string NumG9(double v) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

// The shortest "%g" text that reads back as exactly v (up to 17 digits):
// 0.25 as "0.25", 1 + 2^-52 as "1.0000000000000002", so that a message
// never shows a value outside a range as one inside it.
inline std::string ExactText(double v) {
  char buf[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

// `s` with every character that could rewrite a terminal or reorder the
// text around it shown as an escape: the C0 controls and DEL as \n, \t, \r
// or \xNN; in UTF-8, the C1 controls (U+0080 to U+009F) and the
// bidirectional embeddings, overrides and isolates (U+202A to U+202E,
// U+2066 to U+2069) as \u{NNNN}. Everything else is kept as it is.
inline std::string Printable(const std::string& s) {
  std::string out;
  char buf[16];
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const unsigned char c1 = i + 1 < s.size() ? static_cast<unsigned char>(s[i + 1]) : 0;
    const unsigned char c2 = i + 2 < s.size() ? static_cast<unsigned char>(s[i + 2]) : 0;
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      std::snprintf(buf, sizeof(buf), "\\x%02x", c);
      out += buf;
    } else if (c == 0xc2 && c1 >= 0x80 && c1 <= 0x9f) {  // U+0080 to U+009F
      std::snprintf(buf, sizeof(buf), "\\u{%04x}", c1);
      out += buf;
      i += 1;
    } else if (c == 0xe2 && ((c1 == 0x80 && c2 >= 0xaa && c2 <= 0xae) ||
                             (c1 == 0x81 && c2 >= 0xa6 && c2 <= 0xa9))) {
      // U+202A to U+202E, U+2066 to U+2069
      std::snprintf(buf, sizeof(buf), "\\u{%04x}", 0x2000 | ((c1 & 0x3f) << 6) | (c2 & 0x3f));
      out += buf;
      i += 2;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// The choice `given` is a near miss of, or "": the same letters and digits
// in another case or spelling ("three.js", "E-AVG"), one a prefix of the
// other ("three" in "threejs"), or at most one edit in four (an edit:
// insert, delete, substitute, or swap two neighbours).
// `aliases` maps other names to a choice ("ue4" -> "unreal").
inline std::string NearestChoice(const std::string& given, const std::vector<std::string>& choices,
                                 const std::vector<std::pair<std::string, std::string>>& aliases = {}) {
  auto key = [](const std::string& s) {
    std::string k;
    for (char c : s) {
      if (std::isalnum(static_cast<unsigned char>(c))) k += char(std::tolower(static_cast<unsigned char>(c)));
    }
    return k;
  };
  // Edits: insert, delete, substitute, or swap two neighbours (optimal
  // string alignment).
  auto distance = [](const std::string& a, const std::string& b) {
    const size_t n = b.size() + 1;
    std::vector<size_t> d((a.size() + 1) * n);
    for (size_t i = 0; i <= a.size(); ++i) d[i * n] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      for (size_t j = 1; j <= b.size(); ++j) {
        size_t v = std::min({d[(i - 1) * n + j] + 1, d[i * n + j - 1] + 1,
                             d[(i - 1) * n + j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
          v = std::min(v, d[(i - 2) * n + j - 2] + 1);
        }
        d[i * n + j] = v;
      }
    }
    return d[a.size() * n + b.size()];
  };
  const std::string g = key(given);
  if (g.empty()) return "";
  for (const auto& [alias, choice] : aliases) {
    if (g == key(alias)) return choice;
  }
  // A prefix either way counts as one edit; among equals the fewer true
  // edits win ("ggx-anis" is 'ggx-aniso', not 'ggx').
  std::string best;
  std::pair<size_t, size_t> best_d{std::string::npos, std::string::npos};
  for (const std::string& c : choices) {
    const std::string k = key(c);
    if (k.empty()) continue;
    const size_t edits = distance(g, k);
    size_t d = edits;
    if (k.size() >= 3 && (g.rfind(k, 0) == 0 || k.rfind(g, 0) == 0) && g.size() >= 3) d = std::min<size_t>(d, 1);
    if (d <= std::max<size_t>(1, k.size() / 4) && std::make_pair(d, edits) < best_d) {
      best = c;
      best_d = {d, edits};
    }
  }
  return best;
}

// "a, b or c" (`last` = " or "), "a, b and c" (" and "): a message's list.
inline std::string JoinList(const std::vector<std::string>& names, const char* last) {
  std::string list;
  for (size_t i = 0; i < names.size(); ++i) list += (i == 0 ? "" : i + 1 == names.size() ? last : ", ") + names[i];
  return list;
}
// The choices of a message: "a, b or c".
inline std::string OrList(const std::vector<std::string>& names) { return JoinList(names, " or "); }

// "; did you mean 'x'?" for NearestChoice x, else "".
inline std::string DidYouMean(const std::string& given, const std::vector<std::string>& choices,
                              const std::vector<std::pair<std::string, std::string>>& aliases = {}) {
  const std::string near = NearestChoice(given, choices, aliases);
  return near.empty() ? "" : "; did you mean '" + near + "'?";
}

// `s` for a message: whole up to `max` bytes, else its first `max` bytes
// (cut before a UTF-8 continuation byte) and the total size, so that a
// name or value of megabytes from a file does not fill the error line.
inline std::string Excerpt(const std::string& s, size_t max = 64) {
  if (s.size() <= max) return s;
  size_t n = max;
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xc0) == 0x80) --n;
  return s.substr(0, n) + "... (" + std::to_string(s.size()) + " bytes)";
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BASE_TEXT_H_
