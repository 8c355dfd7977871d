#include "Removed_on_interrupt.h"

#include "Io_error.h"
#include "atomic_write.h"

#include <signal.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cstring>
#include <iterator>
#include <stdexcept>

namespace cgal_policies {
namespace io {
namespace {

// The handler may only read memory that is never allocated or freed: fixed slots, each armed
// through a lock-free atomic once its path is complete.
enum Slot_state : int { slot_free, slot_filling, slot_armed };
struct Slot {
  std::atomic<int> state{slot_free};
  char path[4096];
};
static_assert(std::atomic<int>::is_always_lock_free);

// A few files at once at most: the temporaries of write_all_atomically and the files it renamed
// already (kMaxFilesWrittenAtOnce + 1 at its peak), and a finished picture waiting for its mesh.
Slot g_slots[kMaxFilesWrittenAtOnce + 2];
char g_message[256] = "interrupted\n";
std::size_t g_message_length = std::strlen(g_message);

extern "C" void on_interrupt(int signal) {
  for (Slot& slot : g_slots)
    if (slot.state.load() == slot_armed) ::unlink(slot.path);
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, g_message, g_message_length);
  ::_exit(128 + signal);
}

}  // namespace

void install_interrupt_handlers(const char* app) {
  const std::string message = std::string(app) + ": interrupted\n";
  const std::size_t length = std::min(message.size(), sizeof g_message - 1);
  std::memcpy(g_message, message.data(), length);
  g_message_length = length;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // The second signal waits: the files are removed once.
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  for (int signal : {SIGINT, SIGTERM}) ::sigaction(signal, &action, nullptr);
}

Removed_on_interrupt::Removed_on_interrupt(const std::string& path) : m_slot(-1) {
  if (path.size() >= sizeof g_slots[0].path)
    throw Io_error(Io_error::Kind::unwritable_output, path + ": path too long");
  for (int i = 0; i < int(std::size(g_slots)) && m_slot < 0; ++i) {
    int expected = slot_free;
    if (g_slots[i].state.compare_exchange_strong(expected, slot_filling)) m_slot = i;
  }
  if (m_slot < 0) throw std::logic_error("Removed_on_interrupt: every slot is in use");
  std::memcpy(g_slots[m_slot].path, path.c_str(), path.size() + 1);
  g_slots[m_slot].state.store(slot_armed);
}

Removed_on_interrupt::~Removed_on_interrupt() { g_slots[m_slot].state.store(slot_free); }

}  // namespace io
}  // namespace cgal_policies
