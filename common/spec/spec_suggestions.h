#pragma once
// What to tell a user whose spec file names a field or an enum value the message does not
// have: the nearest name (a typo) or the names there are. The reader (spec_reader.cc) turns
// protobuf's wording into these, for text format and JSON alike:
//
//   unknown field 'probabilty' in task (did you mean 'probability'?)
//   'HUMANS' is not a value of model: BOTH, ROBOT or HUMAN (did you mean HUMAN?)

#include <google/protobuf/descriptor.h>

#include <string>
#include <vector>

namespace envdesign::spec {

// The name in `names` nearest to `written` in edit distance (one letter added, removed,
// changed, or two neighbours swapped; case ignored), if it is near enough to be a typo: at
// most a third of the letters of `written`, at least one. Empty otherwise; the first of
// equally near names.
std::string nearest_name(const std::string &written, const std::vector<std::string> &names);

// "unknown field 'WRITTEN' in task (did you mean 'probability'?)", or without a near name
// "unknown field 'WRITTEN' in task; its fields are name, problem, ...". `shown` is how the
// field is named in the message (a JSON path "task[0].probabilty", or WRITTEN).
std::string unknown_field_message(const google::protobuf::Descriptor &type,
                                  const std::string &written, const std::string &shown);

// "'WRITTEN' is not a value of FIELD: BOTH, ROBOT or HUMAN (did you mean HUMAN?)".
std::string bad_enum_message(const google::protobuf::EnumDescriptor &type, const std::string &field,
                             const std::string &written);

// The message type of the field at `path` from DesignProblem ("modification[0].edit[1]" ->
// Edit; "" -> DesignProblem); nullptr when the path names no message.
const google::protobuf::Descriptor *message_type_at(const std::string &path);

// The enum type of the spec's fields named `field` ("model" -> Edit.Model); nullptr when no
// enum field has that name, or fields of two enum types do.
const google::protobuf::EnumDescriptor *enum_of_field(const std::string &field);

} // namespace envdesign::spec
