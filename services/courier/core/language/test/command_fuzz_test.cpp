// Thousands of random and mutated commands (seeded, so a failure repeats): no crash, and every
// answer is either accepted with a usable interpretation or rejected with a reason whose word and
// column point into the text.
#include "services/courier/core/language/command_tokens.hpp"
#include "services/courier/core/language/structured_request.hpp"
#include "services/courier/core/language/test/language_fixture.hpp"

#include <map>
#include <random>
#include <set>

namespace autonomy::courier {
namespace {

const std::vector<std::string> kSeeds = {
    "put the red letter on the meeting table in room A-111 on the desk in room A-120",
    "deliver the green book from the librarian's desk in room A-110 to the desk in room A-114",
    "pick up the letter from Wolfram and deliver it",
    "deliver the green book to Michael by 10:30",
    "bring the red book from the librarian to room A-114 within 20 minutes",
    "take the blue letter to A-116 before 11",
    "deliver letter-3 to Anna in half an hour",
    "cancel job j7",
    "change the destination of job j7 to Michael",
    "change the deadline of job j7 to 11:30",
    "deliver job j7 by 11:30",
};

const std::vector<std::string> kWords = {"put",     "deliver",  "bring",       "take",
                                         "pick",    "up",       "cancel",      "change",
                                         "the",     "a",        "an",          "it",
                                         "and",     "from",     "to",          "on",
                                         "at",      "in",       "into",        "by",
                                         "before",  "within",   "until",       "room",
                                         "desk",    "table",    "meeting",     "job",
                                         "j7",      "of",       "destination", "deadline",
                                         "red",     "green",    "white",       "letter",
                                         "book",    "envelope", "letter-4",    "A-111",
                                         "A-120",   "A-114",    "A-122",       "librarian's",
                                         "Michael", "Wolfram",  "Anna",        "Jan's",
                                         "10:30",   "11",       "25:00",       "2",
                                         "pm",      "minutes",  "hours",       "half",
                                         "please",  ",",        ".",           "'s",
                                         "mail",    "tray",     "?",           "xyzzy",
                                         "0",       "99999",    "noon",        "\xE2\x80\x99s",
                                         "-",       ":",        "''"};

// Checks the contract of one answer; returns its reason name ("" when accepted).
std::string check_answer(const std::string& text, const CommandAnswer& a,
                         const OfficeKnowledge& k) {
  const int length = static_cast<int>(text.size());
  SCOPED_TRACE("text: [" + text.substr(0, 120) + "]  answer: " + a.summary());
  if (a.kind == CommandAnswer::Kind::delivery) {
    const Interpretation& d = a.delivery;
    EXPECT_FALSE(d.object.kind.empty());
    EXPECT_NE(k.find_place(d.pickup_place), nullptr);
    EXPECT_NE(k.find_place(d.delivery_place), nullptr);
    EXPECT_NE(d.pickup_place, d.delivery_place);
    if (!d.object.id.empty()) {
      EXPECT_NE(k.find_object(d.object.id), nullptr);
    }
    if (d.deadline_s) {
      EXPECT_GT(*d.deadline_s, k.clock.time_of_day(test::kNowSim));
      EXPECT_LE(*d.deadline_s, kSecondsPerDay);
    }
    return "";
  }
  if (a.kind == CommandAnswer::Kind::revision) {
    const Revision& r = a.revision;
    EXPECT_FALSE(r.job.empty());
    EXPECT_GE(r.job_column, 1);
    EXPECT_LE(r.job_column, length);
    if (r.job_column >= 1 && r.job_column <= length) {
      EXPECT_EQ(text.substr(r.job_column - 1, r.job.size()), r.job);
    }
    if (!r.delivery_place.empty()) {
      EXPECT_NE(k.find_place(r.delivery_place), nullptr);
    }
    return "";
  }
  const Rejection& r = a.rejection;
  EXPECT_FALSE(r.message.empty());
  EXPECT_GE(r.column, 1);
  EXPECT_LE(r.column, length + 1);
  EXPECT_TRUE(r.field.empty());
  if (r.reason != RejectReason::bad_character && !r.word.empty() && r.column >= 1 &&
      r.column <= length) {
    EXPECT_EQ(text.substr(r.column - 1, r.word.size()), r.word);
  }
  return to_string(r.reason);
}

class CommandFuzz : public ::testing::Test {
 protected:
  CommandFuzz() {
    k.learned.record("Wolfram", "letter", "michael-desk");
    k.people[1].roles = {"secretary"};
    k.people[2].roles = {"secretary"};
  }
  // Interprets `text` twice (answers must repeat) and checks the contract.
  std::string run(const std::string& text) {
    const CommandAnswer a = interpret_command(text, k, test::kNowSim);
    EXPECT_EQ(interpret_command(text, k, test::kNowSim).summary(), a.summary());
    return check_answer(text, a, k);
  }
  OfficeKnowledge k = test::paper_office();
  std::mt19937_64 rng{20260901};
  std::size_t pick(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  }
};

TEST_F(CommandFuzz, RandomBytes) {
  std::map<std::string, int> reasons;
  for (int n = 0; n < 2000; ++n) {
    std::string text(pick(90), ' ');
    for (char& c : text) {
      const std::size_t r = pick(10);
      c = static_cast<char>(r < 7 ? 0x20 + pick(95) : r < 9 ? 'a' + pick(26) : pick(256));
    }
    ++reasons[run(text)];
  }
  EXPECT_GE(reasons.size(), 3u);  // empty, bad characters, unknown verbs at least
  EXPECT_GT(reasons["bad_character"], 0);
  EXPECT_GT(reasons["unknown_verb"], 0);
}

TEST_F(CommandFuzz, RandomWordSequences) {
  std::map<std::string, int> reasons;
  for (int n = 0; n < 3000; ++n) {
    std::string text;
    const std::size_t words = 1 + pick(14);
    for (std::size_t w = 0; w < words; ++w) text += (w ? " " : "") + kWords[pick(kWords.size())];
    ++reasons[run(text)];
  }
  EXPECT_GE(reasons.size(), 8u);
}

TEST_F(CommandFuzz, MutatedCommands) {
  std::map<std::string, int> reasons;
  for (int n = 0; n < 6000; ++n) {
    std::string text = kSeeds[pick(kSeeds.size())];
    const std::size_t mutations = 1 + pick(3);
    for (std::size_t m = 0; m < mutations && !text.empty(); ++m) {
      const std::size_t at = pick(text.size());
      switch (pick(7)) {
        case 0:
          text.erase(at, 1);
          break;
        case 1:
          text.insert(at, 1, static_cast<char>(0x20 + pick(95)));
          break;
        case 2:
          text[at] = static_cast<char>(0x20 + pick(95));
          break;
        case 3:
          if (at + 1 < text.size()) std::swap(text[at], text[at + 1]);
          break;
        case 4:
          text.insert(at, " " + kWords[pick(kWords.size())] + " ");
          break;
        case 5: {  // delete a word
          const std::size_t end = text.find(' ', at);
          text.erase(at, end == std::string::npos ? std::string::npos : end - at);
          break;
        }
        case 6:
          text.resize(at);
          break;
      }
    }
    ++reasons[run(text)];
  }
  EXPECT_GT(reasons[""], 100);  // many mutations keep a valid command
  EXPECT_GE(reasons.size(), 12u);
}

TEST_F(CommandFuzz, LengthsAroundTheMaximum) {
  const std::string seed = kSeeds[1] + " ";
  for (std::size_t length :
       {kMaxCommandBytes - 1, kMaxCommandBytes, kMaxCommandBytes + 1, 4096ul}) {
    std::string text;
    while (text.size() < length) text += seed;
    text.resize(length);
    const std::string reason = run(text);
    if (length > kMaxCommandBytes)
      EXPECT_EQ(reason, "too_long");
    else
      EXPECT_NE(reason, "too_long");
  }
}

TEST_F(CommandFuzz, StructuredRequests) {
  const std::vector<std::string> values = {
      "",      "letter",    "book",      "red",   "green", "letter-4", "Jan",   "Anna",     "A-114",
      "A-122", "librarian", "secretary", "10:30", "9:00",  "25:00",    "x\x01", "mail room"};
  int accepted = 0;
  for (int n = 0; n < 3000; ++n) {
    StructuredRequest r;
    for (std::string* f : {&r.object_id, &r.kind, &r.colour, &r.from, &r.to, &r.deadline})
      if (pick(3) == 0) *f = values[pick(values.size())];
    const CommandAnswer a = interpret_request(r, k, test::kNowSim);
    SCOPED_TRACE(a.summary());
    if (a.accepted()) {
      ++accepted;
      EXPECT_EQ(a.kind, CommandAnswer::Kind::delivery);
      EXPECT_NE(k.find_place(a.delivery.pickup_place), nullptr);
      EXPECT_NE(k.find_place(a.delivery.delivery_place), nullptr);
    } else {
      EXPECT_FALSE(a.rejection.message.empty());
      EXPECT_FALSE(a.rejection.field.empty());
      EXPECT_EQ(a.rejection.column, 0);
    }
  }
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace autonomy::courier
