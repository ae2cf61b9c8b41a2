#include "core/phonetics/EspeakFreshSynthesis.h"

#include "core/common/Error.h"
#include "core/phonetics/EspeakEngine.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vl {

namespace {

// A byte stream written and read in order: the request (voice, rate, text) and the answer.
class Wire {
  public:
    void u64(std::uint64_t v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); }
    void f64(double v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); }
    void text(std::string_view s) {
        u64(s.size());
        bytes.append(s);
    }
    std::string bytes;
};

class Reader {
  public:
    explicit Reader(std::string_view bytes) : rest_(bytes) {}
    std::uint64_t u64() { return take<std::uint64_t>(); }
    double f64() { return take<double>(); }
    std::string text() {
        const std::uint64_t n = u64();
        if (n > rest_.size()) throw std::runtime_error("espeak-ng child: truncated answer");
        std::string s(rest_.substr(0, n));
        rest_.remove_prefix(n);
        return s;
    }

  private:
    template <class T> T take() {
        if (rest_.size() < sizeof(T)) throw std::runtime_error("espeak-ng child: truncated answer");
        T v;
        std::memcpy(&v, rest_.data(), sizeof v);
        rest_.remove_prefix(sizeof v);
        return v;
    }
    std::string_view rest_;
};

bool sendAll(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

std::string readToEnd(int fd) {
    std::string all;
    char buffer[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return all;
        all.append(buffer, static_cast<std::size_t>(n));
    }
}

enum Answer : std::uint64_t { kSpoken = 0, kInputError = 1, kFailure = 2 };

// In the child of the helper: speaks the request read from `fd` and writes the answer to it.
[[noreturn]] void speakOnce(int fd) {
    Wire answer;
    try {
        const std::string request = readToEnd(fd);
        Reader in(request);
        SpeechVoice voice;
        voice.voice = in.text();
        voice.wordsPerMinute = static_cast<int>(in.u64());
        const std::string text = in.text();
        auto synthesizer = makeEspeakSynthesizer(voice);
        Utterance utterance;
        synthesizer->speak(text, utterance);
        answer.u64(kSpoken);
        answer.u64(static_cast<std::uint64_t>(utterance.sampleRate));
        answer.u64(utterance.phonemes.size());
        for (const TimedPhoneme& p : utterance.phonemes) {
            answer.text(p.phoneme);
            answer.f64(p.start);
            answer.f64(p.end);
        }
        answer.text({reinterpret_cast<const char*>(utterance.samples.data()),
                     utterance.samples.size() * sizeof(std::int16_t)});
        answer.u64(synthesizer->skippedSymbols().size());
        for (const auto& [symbol, count] : synthesizer->skippedSymbols()) {
            answer.text(symbol);
            answer.u64(count);
        }
    } catch (const InputError& e) {
        answer.bytes.clear();
        answer.u64(kInputError);
        answer.text(e.what());
    } catch (const std::exception& e) {
        answer.bytes.clear();
        answer.u64(kFailure);
        answer.text(e.what());
    }
    sendAll(fd, answer.bytes);
    ::_exit(0); // no atexit handlers or destructors of the parent's objects
}

// The helper: initialises espeak-ng, then forks a child per socket received on `control`; exits
// when `control` closes (the FreshSpeech is gone or its process died).
[[noreturn]] void serve(int control) {
    std::signal(SIGCHLD, SIG_IGN); // children are reaped by the kernel
    try {
        std::lock_guard lock(espeak::engineMutex());
        espeak::ensureInitialised();
    } catch (const std::exception&) {
        // Each child reports the failure when it speaks.
    }
    for (;;) {
        char byte = 0;
        iovec io{&byte, 1};
        alignas(cmsghdr) char space[CMSG_SPACE(sizeof(int))] = {};
        msghdr message{};
        message.msg_iov = &io;
        message.msg_iovlen = 1;
        message.msg_control = space;
        message.msg_controllen = sizeof space;
        const ssize_t n = ::recvmsg(control, &message, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) ::_exit(0);
        const cmsghdr* header = CMSG_FIRSTHDR(&message);
        if (!header || header->cmsg_type != SCM_RIGHTS) continue;
        int fd = -1;
        std::memcpy(&fd, CMSG_DATA(header), sizeof fd);
        const pid_t child = ::fork();
        if (child == 0) {
            ::close(control);
            speakOnce(fd);
        }
        ::close(fd); // a failed fork closes the socket: the parent reads an empty answer
    }
}

} // namespace

FreshSpeech::FreshSpeech() {
    int pair[2];
    if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, pair) != 0)
        throw std::runtime_error(std::string("espeak-ng helper: socketpair: ") + std::strerror(errno));
    helper_ = ::fork();
    if (helper_ < 0) {
        ::close(pair[0]);
        ::close(pair[1]);
        throw std::runtime_error(std::string("espeak-ng helper: fork: ") + std::strerror(errno));
    }
    if (helper_ == 0) {
        ::close(pair[0]);
        serve(pair[1]);
    }
    ::close(pair[1]);
    control_ = pair[0];
}

FreshSpeech::~FreshSpeech() {
    ::close(control_);
    int status = 0;
    while (::waitpid(helper_, &status, 0) < 0 && errno == EINTR) {
    }
}

FreshSpeech::Spoken FreshSpeech::speak(const SpeechVoice& voice, std::string_view text) const {
    int pair[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
        throw std::runtime_error(std::string("espeak-ng helper: socketpair: ") + std::strerror(errno));
    {
        char byte = 0;
        iovec io{&byte, 1};
        alignas(cmsghdr) char space[CMSG_SPACE(sizeof(int))] = {};
        msghdr message{};
        message.msg_iov = &io;
        message.msg_iovlen = 1;
        message.msg_control = space;
        message.msg_controllen = sizeof space;
        cmsghdr* header = CMSG_FIRSTHDR(&message);
        header->cmsg_level = SOL_SOCKET;
        header->cmsg_type = SCM_RIGHTS;
        header->cmsg_len = CMSG_LEN(sizeof(int));
        std::memcpy(CMSG_DATA(header), &pair[1], sizeof(int));
        std::lock_guard lock(sending_);
        const ssize_t sent = ::sendmsg(control_, &message, MSG_NOSIGNAL);
        ::close(pair[1]);
        if (sent != 1) {
            ::close(pair[0]);
            throw std::runtime_error("espeak-ng helper: not running");
        }
    }
    Wire request;
    request.text(voice.voice);
    request.u64(static_cast<std::uint64_t>(voice.wordsPerMinute));
    request.text(text);
    const bool sent = sendAll(pair[0], request.bytes);
    ::shutdown(pair[0], SHUT_WR);
    const std::string answer = readToEnd(pair[0]);
    ::close(pair[0]);
    if (!sent || answer.empty()) throw std::runtime_error("espeak-ng child process died while speaking");
    Reader in(answer);
    const std::uint64_t kind = in.u64();
    if (kind == kInputError) throw InputError(in.text());
    if (kind != kSpoken) throw std::runtime_error(in.text());
    Spoken spoken;
    Utterance& u = spoken.utterance;
    u.sampleRate = static_cast<int>(in.u64());
    u.phonemes.resize(in.u64());
    for (TimedPhoneme& p : u.phonemes) {
        p.phoneme = in.text();
        p.start = in.f64();
        p.end = in.f64();
    }
    const std::string samples = in.text();
    u.samples.resize(samples.size() / sizeof(std::int16_t));
    std::memcpy(u.samples.data(), samples.data(), u.samples.size() * sizeof(std::int16_t));
    for (std::uint64_t n = in.u64(); n > 0; --n) {
        std::string symbol = in.text();
        spoken.skippedSymbols[symbol] = in.u64();
    }
    return spoken;
}

} // namespace vl
