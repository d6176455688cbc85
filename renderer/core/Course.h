// Courses: the lessons of scenes/lessons ordered into a class of a given length
// (scenes/courses.json), each lesson with the minutes it takes and one sentence that carries
// the course's thread to it. Read by the GUI's --course and Lessons menu; checked by tests.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sl {

/// The longest `thread` (bytes): one sentence, shown under the lesson's title. A 15 MB one
/// took 52 s and 1.16 GB to lay out.
inline constexpr std::size_t kMaxCourseThreadBytes = 300;

struct CourseLesson {
  std::string lesson;  ///< file name in the lesson folder, e.g. "01-perspective-aliasing.json"
  int minutes = 0;     ///< the time the lesson takes in class
  std::string thread;  ///< one sentence: why this lesson comes here (plain text)
};

struct Course {
  std::string name;  ///< what --course names, e.g. "45"
  int minutes = 0;   ///< the length of the class
  std::vector<CourseLesson> lessons;

  /// The minutes of all its lessons together (at most `minutes` in a valid file).
  int plannedMinutes() const;
};

/// The course file next to the lesson folder: <sceneDir>/courses.json.
std::filesystem::path courseFile(const std::filesystem::path& sceneDir);

/// Reads `{"courses": [{"name", "minutes", "lessons": [{"lesson", "minutes", "thread"}]}]}`.
/// Refused, with one line "FILE: PATH: what is wrong" in `error`, when the JSON is malformed,
/// a lesson is not a file in `lessonDir`, a lesson is listed twice in one course, the
/// lessons' minutes add up to more than the course's, a thread is longer than
/// kMaxCourseThreadBytes, or two courses share a name.
std::optional<std::vector<Course>> loadCourses(const std::filesystem::path& file,
                                               const std::filesystem::path& lessonDir,
                                               std::string* error);

/// The course called `name`; nullptr when none is.
const Course* findCourse(const std::vector<Course>& courses, const std::string& name);
/// "unknown course 'NAME' (known: 90, 45)".
std::string unknownCourseMessage(const std::vector<Course>& courses, const std::string& name);

}  // namespace sl
