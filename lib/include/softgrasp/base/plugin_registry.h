#ifndef softgrasp_base_plugin_registry_h
#define softgrasp_base_plugin_registry_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <map>
#include <memory>
#include <softgrasp/base/input_error.h>
#include <string>

namespace softgrasp
{
  /**
   * A registry of named implementations of one interface @p Interface, in
   * the spirit of ASPECT's plugin system: each implementation registers
   * itself from its own source file (see SOFTGRASP_REGISTER_PLUGIN), so the
   * code that uses the interface never lists the implementations. Creating
   * an unknown name throws an InputError that lists the valid names.
   *
   * @p Interface must provide
   *   static void declare_parameters(ParameterHandler &) per implementation,
   * passed at registration.
   */
  template <typename Interface> class PluginRegistry
  {
  public:
    struct Entry
    {
      std::string                                     description;
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      std::function<std::unique_ptr<Interface>()>     create;
    };

    /// Register @p name; returns true so it can initialize a static bool.
    static bool
    register_plugin(const std::string                              &name,
                    const std::string                              &description,
                    std::function<void(dealii::ParameterHandler &)> declare,
                    std::function<std::unique_ptr<Interface>()>     create)
    {
      entries().emplace(
          name, Entry{description, std::move(declare), std::move(create)});
      return true;
    }

    /// A new default-constructed instance of plugin @p name.
    static std::unique_ptr<Interface> create(const std::string &name,
                                             const std::string &what)
    {
      const auto it = entries().find(name);
      if (it == entries().end())
        throw InputError("Unknown " + what + " '" + name +
                         "'. Valid names are: " + names_separated_by(", ") +
                         ". Fix: use one of them.");
      return it->second.create();
    }

    /// All registered names joined by @p separator, in alphabetical order.
    static std::string names_separated_by(const std::string &separator)
    {
      std::string out;
      for (const auto &[name, entry] : entries())
        out += (out.empty() ? "" : separator) + name;
      return out;
    }

    /// The map of all registered plugins, sorted by name.
    static const std::map<std::string, Entry> &all()
    {
      return entries();
    }

  private:
    // Function-local static: safe against static initialization order.
    static std::map<std::string, Entry> &entries()
    {
      static std::map<std::string, Entry> map;
      return map;
    }
  };
} // namespace softgrasp

/**
 * Register class @p Class (derived from @p Interface, default-constructible,
 * with a static declare_parameters(ParameterHandler&)) under @p name.
 */
#define SOFTGRASP_REGISTER_PLUGIN(Interface, Class, name, description)         \
  namespace                                                                    \
  {                                                                            \
    [[maybe_unused]] const bool softgrasp_registered_##Class =                 \
        ::softgrasp::PluginRegistry<Interface>::register_plugin(               \
            name,                                                              \
            description,                                                       \
            &Class::declare_parameters,                                        \
            []() -> std::unique_ptr<Interface>                                 \
            { return std::make_unique<Class>(); });                            \
  }

#endif
