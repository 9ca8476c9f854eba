#include "interruption.h"

#include "shadowkit/app/commands.h"

namespace shadowkit::sun_study {
namespace {

volatile std::sig_atomic_t signal_received = 0;

extern "C" void note_signal(int signal) {
  signal_received = signal;
}

}  // namespace

Interruption::Interruption()
    : previous_int_(std::signal(SIGINT, note_signal)),
      previous_term_(std::signal(SIGTERM, note_signal)) {
  signal_received = 0;
}

Interruption::~Interruption() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

void Interruption::check() const {
  if (signal_received != 0) throw Interrupted(int(signal_received));
}

}  // namespace shadowkit::sun_study
