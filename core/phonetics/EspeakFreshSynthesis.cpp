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

constexpr std::size_t kMaxVoiceBytes = 256;

// One message of the control sockets: a few bytes (a voice name) and room for one socket.
struct SocketMessage {
    explicit SocketMessage(char* data, std::size_t size) : io{data, size} {
        header.msg_iov = &io;
        header.msg_iovlen = 1;
        header.msg_control = space;
        header.msg_controllen = sizeof space;
    }
    iovec io;
    alignas(cmsghdr) char space[CMSG_SPACE(sizeof(int))] = {};
    msghdr header{};
};

// Receives one message of `control`: its bytes and the socket it carries (-1 when none). False at
// the end (the sender closed its side).
bool receive(int control, std::string& bytes, int& fd) {
    char buffer[kMaxVoiceBytes];
    SocketMessage message(buffer, sizeof buffer);
    ssize_t n = 0;
    while ((n = ::recvmsg(control, &message.header, 0)) < 0 && errno == EINTR) {
    }
    if (n <= 0) return false;
    bytes.assign(buffer, static_cast<std::size_t>(n));
    fd = -1;
    if (const cmsghdr* header = CMSG_FIRSTHDR(&message.header); header && header->cmsg_type == SCM_RIGHTS)
        std::memcpy(&fd, CMSG_DATA(header), sizeof fd);
    return true;
}

// Sends `bytes` (at most kMaxVoiceBytes) and the socket `fd` as one message.
bool sendWithSocket(int control, std::string_view bytes, int fd) {
    SocketMessage message(const_cast<char*>(bytes.data()), bytes.size());
    cmsghdr* header = CMSG_FIRSTHDR(&message.header);
    header->cmsg_level = SOL_SOCKET;
    header->cmsg_type = SCM_RIGHTS;
    header->cmsg_len = CMSG_LEN(sizeof(int));
    std::memcpy(CMSG_DATA(header), &fd, sizeof fd);
    return ::sendmsg(control, &message.header, MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size());
}

// A voice's helper: selects the voice once (listing espeak-ng's voices costs more than speaking a
// sentence), then forks a child per socket received; exits when `control` closes.
[[noreturn]] void serveVoice(int control, const std::string& voice) {
    try {
        std::lock_guard lock(espeak::engineMutex());
        espeak::selectVoice(voice);
    } catch (const std::exception&) {
        // Each child selects it again and reports the error.
    }
    std::string bytes;
    int fd = -1;
    while (receive(control, bytes, fd)) {
        if (fd < 0) continue;
        if (::fork() == 0) {
            ::close(control);
            speakOnce(fd);
        }
        ::close(fd); // a failed fork closes the socket: the parent reads an empty answer
    }
    ::_exit(0);
}

// The helper: initialises espeak-ng, then passes each socket to the helper of its voice (forked on
// first use: its state is Initialize + SetVoiceByName, a fresh `say`'s); exits when `control`
// closes (the FreshSpeech is gone or its process died), and so do the voices' helpers.
[[noreturn]] void serve(int control) {
    std::signal(SIGCHLD, SIG_IGN); // children are reaped by the kernel
    try {
        std::lock_guard lock(espeak::engineMutex());
        espeak::ensureInitialised();
    } catch (const std::exception&) {
        // Each child reports the failure when it speaks.
    }
    std::map<std::string, int> voices; // voice -> its helper's control socket
    std::string voice;
    int fd = -1;
    while (receive(control, voice, fd)) {
        if (fd < 0) continue;
        auto it = voices.find(voice);
        if (it == voices.end()) {
            int pair[2];
            if (::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, pair) == 0) {
                if (::fork() == 0) {
                    ::close(control);
                    ::close(pair[0]);
                    ::close(
                        fd); // it comes again as the first message: a copy kept would hold the socket open
                    for (const auto& [name, other] : voices) ::close(other);
                    serveVoice(pair[1], voice);
                }
                ::close(pair[1]);
                it = voices.emplace(voice, pair[0]).first;
            }
        }
        if (it != voices.end()) sendWithSocket(it->second, voice, fd);
        ::close(fd);
    }
    ::_exit(0);
}

} // namespace

FreshSpeech::FreshSpeech() {
    {
        std::lock_guard lock(espeak::engineMutex());
        if (espeak::hasSpoken())
            throw std::logic_error(
                "FreshSpeech made after this process spoke: its helper would not be fresh");
    }
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
    if (voice.voice.empty() || voice.voice.size() > kMaxVoiceBytes)
        throwInputError("voice '" + voice.voice + "'", "espeak-ng has no such voice");
    {
        std::lock_guard lock(sending_);
        const bool sent = sendWithSocket(control_, voice.voice, pair[1]);
        ::close(pair[1]);
        if (!sent) {
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
