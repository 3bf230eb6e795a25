// Percentage-closer filtering (Reeves, Salesin and Cook 1987): the weighted share of a kernel's taps
// that pass, each against its own texel.
#include "lookup/lookup_settings.hpp"
#include "lookup/shadow_reader.hpp"
#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

std::vector<KernelTap> kernel(const ShadowFilter& f) { return kernel_taps(f.kernel, f.kernel_size); }
int kernel_reads(const ShadowFilter& f) { return f.kernel_size * f.kernel_size; }
bool turns(const ShadowFilter& f) { return f.kernel == PcfKernel::poisson; }

// The kernel's radius in texels: its world radius across the light where one is set; the Poisson
// disk turned per pixel.
double percentage_closer(const ShadowReader& reader, const MapReceiver& m, const Receiver& r, LookupCount* count) {
    const ShadowFilter& f = reader.lookup().filter;
    const double radius = f.radius_world > 0.0 ? f.radius_world / m.texel_world : f.radius_texels;
    return reader.lit_share(m, reader.taps(), finite_or(radius, 0.0), turns(f) ? r.rotation : 0.0, count);
}

}  // namespace

FilterDescriptor pcf_filter() {
    return {.name = "pcf",
            .description =
                "percentage-closer filtering: the weighted share of a box, tent or Poisson kernel's taps "
                "that pass",
            .settings = {{.name = "pcf_kernel",
                          .description = "pcf: box or tent N×N taps, or a Poisson disk of N² taps turned per pixel",
                          .default_value = "box",
                          .choices = {"box", "tent", "poisson"}},
                         kernel_size_setting(),
                         {.name = "filter_radius",
                          .description = "pcf: the kernel's half-width in texels of the map",
                          .default_value = "1",
                          .min = 0.01,
                          .max = 32},
                         {.name = "filter_world_radius",
                          .description = "pcf: the kernel's half-width in world units across the light (0: in "
                                         "texels, filter_radius)",
                          .default_value = "0",
                          .min = 0,
                          .max = 1e30,
                          .length_power = 1}},
            .taps = kernel,
            .texel_reads = kernel_reads,
            .turns_taps = turns,
            .visibility = percentage_closer};
}

}  // namespace shadowlab
