// Courses (see Course.h): scenes/courses.json read and checked against the lesson folder.
#include "core/Course.h"

#include <algorithm>
#include <set>
#include <system_error>

#include "core/JsonInput.h"

namespace sl {

int Course::plannedMinutes() const {
  int total = 0;
  for (const CourseLesson& l : lessons) total += l.minutes;
  return total;
}

std::filesystem::path courseFile(const std::filesystem::path& sceneDir) {
  return sceneDir / "courses.json";
}

namespace {
constexpr int kMaxCourseMinutes = 8 * 60;  ///< a day of classes

CourseLesson parseCourseLesson(const JsonReader& r, const nlohmann::json& j,
                               const std::string& path, const std::filesystem::path& lessonDir) {
  r.requireObject(j, path);
  r.onlyKeys(j, path, {"lesson", "minutes", "thread"});
  CourseLesson l;
  const nlohmann::json* lesson = JsonReader::member(j, "lesson");
  if (!lesson) r.fail(path, "needs \"lesson\" (a file name in " + lessonDir.string() + ")");
  l.lesson = r.string(*lesson, jsonPath(path, "lesson"));
  std::error_code ec;
  if (l.lesson.empty() || l.lesson.find('/') != std::string::npos ||
      !std::filesystem::is_regular_file(lessonDir / l.lesson, ec))
    r.fail(jsonPath(path, "lesson"),
           "no lesson '" + quoteText(l.lesson, 80) + "' in " + lessonDir.string());
  const nlohmann::json* minutes = JsonReader::member(j, "minutes");
  if (!minutes) r.fail(path, "needs \"minutes\" (the time the lesson takes)");
  l.minutes = r.integer(*minutes, jsonPath(path, "minutes"), 1, kMaxCourseMinutes);
  l.thread = r.string(j, path, "thread", "");
  if (l.thread.size() > kMaxCourseThreadBytes)
    r.fail(jsonPath(path, "thread"),
           "a text of " + std::to_string(l.thread.size()) + " bytes, over the limit of " +
               std::to_string(kMaxCourseThreadBytes) + " (kMaxCourseThreadBytes: one sentence)");
  return l;
}

Course parseCourse(const JsonReader& r, const nlohmann::json& j, const std::string& path,
                   const std::filesystem::path& lessonDir) {
  r.requireObject(j, path);
  r.onlyKeys(j, path, {"name", "minutes", "lessons"});
  Course c;
  c.name = r.string(j, path, "name", "");
  if (c.name.empty()) r.fail(path, "needs a \"name\" (what --course names)");
  const nlohmann::json* minutes = JsonReader::member(j, "minutes");
  if (!minutes) r.fail(path, "needs \"minutes\" (the length of the class)");
  c.minutes = r.integer(*minutes, jsonPath(path, "minutes"), 1, kMaxCourseMinutes);
  const nlohmann::json* lessons = JsonReader::member(j, "lessons");
  const std::string lessonsPath = jsonPath(path, "lessons");
  if (!lessons) r.fail(path, "needs \"lessons\" (the lessons in their order)");
  r.requireArray(*lessons, lessonsPath);
  if (lessons->empty()) r.fail(lessonsPath, "a course needs at least one lesson");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < lessons->size(); ++i) {
    const std::string at = jsonPath(lessonsPath, i);
    CourseLesson l = parseCourseLesson(r, (*lessons)[i], at, lessonDir);
    if (!seen.insert(l.lesson).second)
      r.fail(jsonPath(at, "lesson"), "'" + l.lesson + "' is listed twice in this course");
    c.lessons.push_back(std::move(l));
  }
  if (c.plannedMinutes() > c.minutes)
    r.fail(lessonsPath, "the lessons take " + std::to_string(c.plannedMinutes()) +
                            " minutes, more than the course's " + std::to_string(c.minutes));
  return c;
}
}  // namespace

std::optional<std::vector<Course>> loadCourses(const std::filesystem::path& file,
                                               const std::filesystem::path& lessonDir,
                                               std::string* error) {
  const JsonReader r(file.string());
  try {
    const nlohmann::json root = r.parseFile();
    r.requireObject(root, "");
    r.onlyKeys(root, "", {"courses"});
    const nlohmann::json* list = JsonReader::member(root, "courses");
    if (!list) r.fail("courses", "missing: the file lists its courses under \"courses\"");
    r.requireArray(*list, "courses");
    std::vector<Course> courses;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string at = jsonPath("courses", i);
      Course c = parseCourse(r, (*list)[i], at, lessonDir);
      if (findCourse(courses, c.name))
        r.fail(jsonPath(at, "name"), "a second course called '" + c.name + "'");
      courses.push_back(std::move(c));
    }
    return courses;
  } catch (const JsonInputError& e) {
    if (error) *error = e.what();
    return std::nullopt;
  }
}

const Course* findCourse(const std::vector<Course>& courses, const std::string& name) {
  const auto it = std::find_if(courses.begin(), courses.end(),
                               [&name](const Course& c) { return c.name == name; });
  return it == courses.end() ? nullptr : &*it;
}

std::string unknownCourseMessage(const std::vector<Course>& courses, const std::string& name) {
  std::string known;
  for (const Course& c : courses) known += (known.empty() ? "" : ", ") + c.name;
  return "unknown course '" + name + "' (known: " + (known.empty() ? "none" : known) + ")";
}

}  // namespace sl
