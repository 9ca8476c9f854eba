// An interrupted study leaves no file behind: the signal is noticed between blocks of steps,
// and every file not yet complete is removed as the run unwinds.
#include "interruption.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>

#include "contract_files.h"
#include "shadowkit/app/commands.h"

namespace shadowkit::sun_study {
namespace {

TEST(Interruption, ASignalIsNoticedAtTheNextCheck) {
  {
    const Interruption interruption;
    EXPECT_NO_THROW(interruption.check());
    std::raise(SIGINT);  // would end the test program without the handler
    try {
      interruption.check();
      ADD_FAILURE() << "no Interrupted";
    } catch (const Interrupted& e) {
      EXPECT_EQ(e.signal, SIGINT);
    }
  }
  const Interruption next;  // a new run starts without the old signal
  EXPECT_NO_THROW(next.check());
}

TEST(Interruption, TheHandlerBeforeComesBack) {
  const auto before = std::signal(SIGTERM, SIG_IGN);
  { const Interruption interruption; }
  EXPECT_EQ(std::signal(SIGTERM, before), SIG_IGN);
}

TEST(AtomicFile, AFileNeverCommittedLeavesNothing) {
  const fs::path dir = fs::temp_directory_path() / "shadowkit_atomic_file";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    AtomicFile file(dir / "times.csv");
    file.stream() << "index,time_utc\n0,";
    EXPECT_TRUE(fs::exists(dir / "times.csv.partial"));
  }
  EXPECT_TRUE(fs::is_empty(dir));
  {
    AtomicFile file(dir / "times.csv");
    file.stream() << "complete\n";
    file.commit();
  }
  EXPECT_EQ(read_file(dir / "times.csv"), "complete\n");
  EXPECT_FALSE(fs::exists(dir / "times.csv.partial"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shadowkit::sun_study
