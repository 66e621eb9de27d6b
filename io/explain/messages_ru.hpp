// Error messages in Russian for exam mode (`hlr explain --lang ru`): the readers, the
// kernel and the algorithms throw English messages built from fixed templates; this catalogue
// holds the Russian of every template a problem file can reach, with the course's words.
#pragma once

#include <string>
#include <vector>

namespace hlr {

/// The Russian text of an English error message (the message part, without "file:line: ").
/// Templates nest ("clipper: <message>", "body 2 <reason>"): each part is translated. A message
/// with no entry is returned unchanged and `*translated` (when given) is set to false.
std::string message_ru(const std::string& english, bool* translated = nullptr);

/// The English templates of the catalogue (placeholders @x, @w, @m), for the test that every
/// message the sources throw has an entry.
std::vector<std::string> message_ru_templates();

}  // namespace hlr
