#include "core/phonetics/EspeakApi.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace vl::espeak {

namespace {

constexpr const char* kLibrary = "libespeak-ng.so.1"; // the soname of espeak-ng 1.x

template <typename Function> void resolve(void* library, const char* name, Function& function) {
    void* symbol = ::dlsym(library, name);
    if (!symbol)
        throw std::runtime_error(std::string(kLibrary) + " has no " + name +
                                 " (espeak-ng 1.49 or newer is needed)");
    function = reinterpret_cast<Function>(symbol);
}

Api load() {
    // Lazy, as espeak-ng's own program binds it: its dependencies (libpcaudio and the sound servers'
    // libraries) export thousands of functions synthesis never calls; binding them all up front cost
    // a `say` 1.7 M instructions (callgrind).
    void* library = ::dlopen(kLibrary, RTLD_LAZY | RTLD_LOCAL);
    if (!library) {
        const char* why = ::dlerror();
        throw std::runtime_error(std::string("cannot load espeak-ng (") + (why ? why : kLibrary) +
                                 "); install it: apt-get install libespeak-ng1 espeak-ng-data");
    }
    Api api;
    resolve(library, "espeak_Initialize", api.Initialize);
    resolve(library, "espeak_SetVoiceByName", api.SetVoiceByName);
    resolve(library, "espeak_SetVoiceByProperties", api.SetVoiceByProperties);
    resolve(library, "espeak_GetCurrentVoice", api.GetCurrentVoice);
    resolve(library, "espeak_ListVoices", api.ListVoices);
    resolve(library, "espeak_TextToPhonemes", api.TextToPhonemes);
    resolve(library, "espeak_SetParameter", api.SetParameter);
    resolve(library, "espeak_SetSynthCallback", api.SetSynthCallback);
    resolve(library, "espeak_Synth", api.Synth);
    return api; // the library stays loaded for the life of the process
}

} // namespace

const Api& api() {
    static const Api loaded = load();
    return loaded;
}

} // namespace vl::espeak
