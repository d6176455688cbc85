// scenes/courses.json: every course lists lessons that exist, each once, within its minutes;
// and a bad course file is refused with one line naming the file, the entry and the problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/Course.h"
#include "core/Preset.h"

namespace sl {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(SHADOWLAB_TEST_DATA) / ".." / ".." / "scenes";
const fs::path kLessons = kScenes / "lessons";

fs::path writeCourses(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(SHADOWLAB_TEST_OUT) / "gl" / "courses";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

std::string loadError(const std::string& name, const std::string& text) {
  const fs::path path = writeCourses(name, text);
  std::string error;
  EXPECT_FALSE(loadCourses(path, kLessons, &error)) << name;
  const std::string prefix = path.string() + ": ";
  EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
  return error.substr(std::min(error.size(), prefix.size()));
}

TEST(Courses, TheCourseFileListsLessonsThatExistOnceWithinTheCourseLength) {
  std::string error;
  const auto courses = loadCourses(courseFile(kScenes), kLessons, &error);
  ASSERT_TRUE(courses) << error;
  ASSERT_NE(findCourse(*courses, "90"), nullptr);
  ASSERT_NE(findCourse(*courses, "45"), nullptr);
  EXPECT_EQ(findCourse(*courses, "90")->minutes, 90);
  EXPECT_EQ(findCourse(*courses, "45")->minutes, 45);
  for (const Course& c : *courses) {
    SCOPED_TRACE("course " + c.name);
    EXPECT_LE(c.plannedMinutes(), c.minutes);
    std::set<std::string> seen;
    for (const CourseLesson& l : c.lessons) {
      EXPECT_TRUE(seen.insert(l.lesson).second) << l.lesson << " listed twice";
      std::string presetError;
      EXPECT_TRUE(loadPreset(kLessons / l.lesson, &presetError)) << presetError;
      EXPECT_GE(l.minutes, 1) << l.lesson;
      EXPECT_FALSE(l.thread.empty()) << l.lesson << ": no sentence";
    }
  }
  // The long class has every lesson, the short one a part of them.
  std::size_t lessonFiles = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(kLessons))
    lessonFiles += e.path().extension() == ".json";
  EXPECT_EQ(findCourse(*courses, "90")->lessons.size(), lessonFiles);
  EXPECT_LT(findCourse(*courses, "45")->lessons.size(), lessonFiles);
}

// docs/lecturer/courses.md shows each course as a table ("| # | minutes | time | N. title |
// thread |"): the same lessons (by their number in the Lessons menu, the sorted file order), in
// the same order, with the same minutes and sentences as scenes/courses.json.
TEST(Courses, TheLecturerPageShowsTheCourseFile) {
  std::string error;
  const auto courses = loadCourses(courseFile(kScenes), kLessons, &error);
  ASSERT_TRUE(courses) << error;
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(kLessons))
    if (e.path().extension() == ".json") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  std::ifstream page(kScenes / ".." / "docs" / "lecturer" / "courses.md");
  ASSERT_TRUE(page) << "docs/lecturer/courses.md";
  std::map<std::string, std::vector<CourseLesson>> shown;  // course name -> its table's rows
  std::string line, current;
  while (std::getline(page, line)) {
    if (line.rfind("## The ", 0) == 0 && line.find("-minute class") != std::string::npos) {
      current = line.substr(7, line.find('-') - 7);
      continue;
    }
    if (line.rfind("## ", 0) == 0) current.clear();
    if (current.empty() || line.rfind("| ", 0) != 0 || line.rfind("| #", 0) == 0) continue;
    std::vector<std::string> cells;
    std::size_t at = 1;
    for (std::size_t bar; (bar = line.find(" |", at)) != std::string::npos; at = bar + 2)
      cells.push_back(line.substr(at + 1, bar - at - 1));
    ASSERT_GE(cells.size(), 5u) << line;
    const int number = std::atoi(cells[3].c_str());
    ASSERT_TRUE(number >= 1 && number <= int(files.size())) << line;
    shown[current].push_back(
        {files[std::size_t(number - 1)], std::atoi(cells[1].c_str()), cells[4]});
  }
  for (const Course& c : *courses) {
    SCOPED_TRACE("course " + c.name);
    const std::vector<CourseLesson>& rows = shown[c.name];
    ASSERT_EQ(rows.size(), c.lessons.size())
        << "the page's table of the " << c.name << "-minute class";
    for (std::size_t k = 0; k < rows.size(); ++k) {
      EXPECT_EQ(rows[k].lesson, c.lessons[k].lesson) << "row " << k + 1;
      EXPECT_EQ(rows[k].minutes, c.lessons[k].minutes) << "row " << k + 1;
      EXPECT_EQ(rows[k].thread, c.lessons[k].thread) << "row " << k + 1;
    }
  }
}

TEST(Courses, BadCourseFilesAreRefusedNamingTheEntry) {
  EXPECT_EQ(loadError("missing.json",
                      R"({"courses": [{"name": "45", "minutes": 45, "lessons": [
                          {"lesson": "01-perspective-aliasing.json", "minutes": 5},
                          {"lesson": "99-nothing.json", "minutes": 5}]}]})"),
            "courses[0].lessons[1].lesson: no lesson '99-nothing.json' in " + kLessons.string());
  EXPECT_EQ(loadError("twice.json",
                      R"({"courses": [{"name": "45", "minutes": 45, "lessons": [
                          {"lesson": "01-perspective-aliasing.json", "minutes": 5},
                          {"lesson": "01-perspective-aliasing.json", "minutes": 5}]}]})"),
            "courses[0].lessons[1].lesson: '01-perspective-aliasing.json' is listed twice in "
            "this course");
  EXPECT_EQ(loadError("long.json",
                      R"({"courses": [{"name": "10", "minutes": 10, "lessons": [
                          {"lesson": "01-perspective-aliasing.json", "minutes": 6},
                          {"lesson": "02-projective-aliasing.json", "minutes": 5}]}]})"),
            "courses[0].lessons: the lessons take 11 minutes, more than the course's 10");
  EXPECT_EQ(loadError("names.json",
                      R"({"courses": [
                          {"name": "a", "minutes": 9, "lessons": [
                            {"lesson": "01-perspective-aliasing.json", "minutes": 5}]},
                          {"name": "a", "minutes": 9, "lessons": [
                            {"lesson": "02-projective-aliasing.json", "minutes": 5}]}]})"),
            "courses[1].name: a second course called 'a'");
  EXPECT_EQ(loadError("outside.json",
                      R"({"courses": [{"name": "a", "minutes": 9, "lessons": [
                          {"lesson": "../courses.json", "minutes": 5}]}]})"),
            "courses[0].lessons[0].lesson: no lesson '../courses.json' in " + kLessons.string());
  EXPECT_EQ(loadError("key.json", R"({"courses": [{"name": "a", "length": 9}]})"),
            "courses[0].length: unknown key 'length' (known: name, minutes, lessons)");
}

// A thread is one sentence (kMaxCourseThreadBytes): the hostile fixture's 400 bytes are
// refused (a 15 MB one took 52 s and 1.16 GB to lay out in the Lesson dock).
TEST(Courses, ThreadsLongerThanASentenceAreRefused) {
  const fs::path fixture =
      fs::path(SHADOWLAB_TEST_DATA) / ".." / "fixtures" / "hostile" / "courses-thread-400.json";
  std::string error;
  EXPECT_FALSE(loadCourses(fixture, kLessons, &error));
  EXPECT_EQ(error, fixture.string() +
                       ": courses[0].lessons[0].thread: a text of 400 bytes, over the limit of "
                       "300 (kMaxCourseThreadBytes: one sentence)");
  const std::string atLimit(kMaxCourseThreadBytes, 'w');
  const fs::path ok = writeCourses("thread-at-limit.json",
                                   R"({"courses": [{"name": "a", "minutes": 9, "lessons": [
                          {"lesson": "01-perspective-aliasing.json", "minutes": 5, "thread": ")" +
                                       atLimit + R"("}]}]})");
  EXPECT_TRUE(loadCourses(ok, kLessons, &error)) << error;
}

TEST(Courses, UnknownCourseNamesTheKnownOnes) {
  const std::vector<Course> courses{{"90", 90, {}}, {"45", 45, {}}};
  EXPECT_EQ(unknownCourseMessage(courses, "30"), "unknown course '30' (known: 90, 45)");
}

}  // namespace
}  // namespace sl
