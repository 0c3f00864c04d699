#include "audio/audio_device.h"

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include <algorithm>

#include "core/error.h"

namespace terrasol {
namespace {

// Music streams on a voice of its own, as do loops; a few to spare.
constexpr int kStereoSources = 4;

ALCdevice* asDevice(void* p) {
  return static_cast<ALCdevice*>(p);
}
ALCcontext* asContext(void* p) {
  return static_cast<ALCcontext*>(p);
}

}  // namespace

AudioDevice::AudioDevice(AudioOutput output, int voices) : output_(output) {
  if (output == AudioOutput::Loopback) {
    if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback"))
      throw Error("OpenAL: no loopback devices (ALC_SOFT_loopback)");
    auto open = reinterpret_cast<LPALCLOOPBACKOPENDEVICESOFT>(
        alcGetProcAddress(nullptr, "alcLoopbackOpenDeviceSOFT"));
    device_ = open ? open(nullptr) : nullptr;
    renderSamples_ = reinterpret_cast<void*>(alcGetProcAddress(asDevice(device_), "alcRenderSamplesSOFT"));
  } else {
    device_ = alcOpenDevice(nullptr);
  }
  if (!device_) throw Error("OpenAL: no audio device to open");
  const ALCint attributes[] = {ALC_MONO_SOURCES,
                               voices,
                               ALC_STEREO_SOURCES,
                               kStereoSources,
                               ALC_FREQUENCY,
                               kLoopbackRate,
                               ALC_FORMAT_CHANNELS_SOFT,
                               ALC_STEREO_SOFT,
                               ALC_FORMAT_TYPE_SOFT,
                               ALC_SHORT_SOFT,
                               0};
  // The format keys are the loopback device's; a speaker device picks its own rate and layout.
  const ALCint speakerAttributes[] = {ALC_MONO_SOURCES, voices, ALC_STEREO_SOURCES, kStereoSources, 0};
  context_ =
      alcCreateContext(asDevice(device_), output == AudioOutput::Loopback ? attributes : speakerAttributes);
  if (!context_ || !alcMakeContextCurrent(asContext(context_))) {
    if (context_) alcDestroyContext(asContext(context_));
    alcCloseDevice(asDevice(device_));
    throw Error("OpenAL: no context on the audio device");
  }
  const ALCchar* name = alcGetString(asDevice(device_), ALC_DEVICE_SPECIFIER);
  name_ = name ? name : "OpenAL";
  alcGetIntegerv(asDevice(device_), ALC_FREQUENCY, 1, &rate_);
  alcGetIntegerv(asDevice(device_), ALC_MONO_SOURCES, 1, &voices_);
  voices_ = std::min(voices_, voices);
  efx_ = alcIsExtensionPresent(asDevice(device_), "ALC_EXT_EFX") == ALC_TRUE;
}

AudioDevice::~AudioDevice() {
  alcMakeContextCurrent(nullptr);
  if (context_) alcDestroyContext(asContext(context_));
  if (device_) alcCloseDevice(asDevice(device_));
}

void AudioDevice::render(std::span<std::int16_t> out) {
  if (output_ != AudioOutput::Loopback || out.empty()) return;
  reinterpret_cast<LPALCRENDERSAMPLESSOFT>(renderSamples_)(asDevice(device_), out.data(),
                                                           static_cast<ALCsizei>(out.size() / 2));
}

}  // namespace terrasol
