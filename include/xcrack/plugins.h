#ifndef xcrack_plugins_h
#define xcrack_plugins_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <xcrack/input_error.h>

#include <algorithm>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * Plugin systems, in the manner of ASPECT: each replaceable part of a run
   * (a direction criterion, a growth law, a level-set update method, a
   * termination criterion, a mesh refinement strategy) is an abstract
   * `Interface<dim>` in its own folder, and every implementation is one
   * file pair that registers itself by name at the end of its .cc file:
   *
   *     XCRACK_REGISTER_PLUGIN(GrowthLaw::Interface, Paris, "paris",
   *                            "da/dN = C (Delta K)^m ...")
   *
   * The selection entry of the parameter file (`Model name`, `Strategy`, a
   * list of termination criteria) is built from the registered names, and
   * each plugin declares and parses its own parameters in its own
   * subsection. Adding a method never means editing a central switch.
   */
  namespace Plugins
  {
    /// What a plugin keeps across steps, as named strings (save(), load()).
    using State = std::map<std::string, std::string>;

    /**
     * What every plugin has: parameters of its own, a start-up hook called
     * once the simulator's state can be read (see SimulatorAccess), and the
     * state it keeps across steps, written with each checkpoint.
     */
    class InterfaceBase
    {
    public:
      virtual ~InterfaceBase() = default;

      /// Declare the plugin's entries (in the subsection it enters itself).
      static void
      declare_parameters(ParameterHandler &)
      {}

      /// Read them; throw InputError naming the entry on bad values.
      virtual void
      parse_parameters(ParameterHandler &)
      {}

      /// Called after parse_parameters() and initialize_simulator().
      virtual void
      initialize()
      {}

      /**
       * Write what the plugin has learnt during the run (counters, initial
       * values, statuses, history) into @p state, for the checkpoint: a run
       * resumed from it must go on as the one that wrote it (ASPECT's
       * save()/load()). Plugins without such state write nothing.
       */
      virtual void
      save(State & /*state*/) const
      {}

      /// Restore what save() wrote (on `--resume`, before the first step).
      virtual void
      load(const State & /*state*/)
      {}

      /// The name the plugin was registered and selected by.
      const std::string &
      plugin_name() const
      {
        return name;
      }

    private:
      std::string name;

      template <typename>
      friend class PluginList;
    };



    /// @p object as bytes in a string, for a plugin's State (any type that
    /// boost serialization or a plain copy can write).
    template <typename T>
    std::string
    pack(const T &object)
    {
      const std::vector<char> bytes = Utilities::pack(object, false);
      return std::string(bytes.begin(), bytes.end());
    }

    /// The object that pack() wrote under @p key of @p state; @p fallback
    /// if there is none.
    template <typename T>
    T
    unpack(const State &state, const std::string &key, const T &fallback)
    {
      const auto it = state.find(key);
      if (it == state.end())
        return fallback;
      return Utilities::unpack<T>(std::vector<char>(it->second.begin(),
                                                    it->second.end()),
                                  false);
    }



    /**
     * The registered implementations of the plugin system whose interface is
     * @p InterfaceType (for one dimension). Registration happens during
     * static initialisation of the library, so every name is known when
     * main() declares the parameters.
     */
    template <typename InterfaceType>
    class PluginList
    {
    public:
      struct Entry
      {
        std::string name;
        std::string description;
        void (*declare_parameters)(ParameterHandler &);
        std::function<std::unique_ptr<InterfaceType>()> create;
      };

      static void
      register_plugin(const std::string &name,
                      const std::string &description,
                      void (*declare_parameters)(ParameterHandler &),
                      std::function<std::unique_ptr<InterfaceType>()> create)
      {
        entries().push_back({name, description, declare_parameters, create});
        std::sort(entries().begin(),
                  entries().end(),
                  [](const Entry &a, const Entry &b) {
                    return a.name < b.name;
                  });
      }

      /// The names as a Patterns::Selection / MultipleSelection string.
      static std::string
      pattern()
      {
        std::string names;
        for (const Entry &e : entries())
          names += (names.empty() ? "" : "|") + e.name;
        return names;
      }

      /// "name: description" of every plugin, for an entry's documentation.
      static std::string
      documentation()
      {
        std::string text;
        for (const Entry &e : entries())
          text += "\n`" + e.name + "`: " + e.description;
        return text;
      }

      /// Let every plugin declare its parameters (in the current subsection).
      static void
      declare_parameters(ParameterHandler &prm)
      {
        for (const Entry &e : entries())
          e.declare_parameters(prm);
      }

      /**
       * A new plugin of registered name @p name, parameters not yet parsed
       * (see SimulatorAccess's create_plugin()). @p entry names the
       * selection entry in the message of an unknown name.
       */
      static std::unique_ptr<InterfaceType>
      create(const std::string &name, const std::string &entry)
      {
        for (const Entry &e : entries())
          if (e.name == name)
            {
              std::unique_ptr<InterfaceType> plugin = e.create();
              plugin->name                          = name;
              return plugin;
            }
        throw InputError(entry + " = " + name +
                         ": no such plugin (known: " + pattern() + ").");
      }

    private:
      /// A function-local static: safe whatever the order of registration.
      static std::vector<Entry> &
      entries()
      {
        static std::vector<Entry> list;
        return list;
      }
    };



    /**
     * Enter a subsection of @p prm for the lifetime of this object, so that
     * an InputError thrown while parsing leaves @p prm where it was.
     */
    class ScopedSubsection
    {
    public:
      ScopedSubsection(ParameterHandler &prm, const std::string &name)
        : prm(prm)
      {
        prm.enter_subsection(name);
      }

      ~ScopedSubsection()
      {
        prm.leave_subsection();
      }

      ScopedSubsection(const ScopedSubsection &) = delete;
      ScopedSubsection &
      operator=(const ScopedSubsection &) = delete;

    private:
      ParameterHandler &prm;
    };



    /// Registers @p PluginType under a name when constructed (statically).
    template <typename InterfaceType, typename PluginType>
    struct Registration
    {
      Registration(const char *name, const char *description)
      {
        PluginList<InterfaceType>::register_plugin(
          name, description, &PluginType::declare_parameters, []() {
            return std::unique_ptr<InterfaceType>(new PluginType());
          });
      }
    };
  } // namespace Plugins
} // namespace xcrack

#define XCRACK_PLUGIN_CONCAT_(a, b) a##b
#define XCRACK_PLUGIN_CONCAT(a, b) XCRACK_PLUGIN_CONCAT_(a, b)

/**
 * Instantiate plugin template @p classname in 2D and 3D and register both
 * under @p name with @p description in the plugin system of @p interface
 * (a class template of the dimension). Use once, at the end of the
 * plugin's .cc file, inside namespace xcrack.
 */
#define XCRACK_REGISTER_PLUGIN(interface, classname, name, description)    \
  template class classname<2>;                                             \
  template class classname<3>;                                             \
  namespace                                                                \
  {                                                                        \
    const ::xcrack::Plugins::Registration<interface<2>, classname<2>>      \
      XCRACK_PLUGIN_CONCAT(registration_2d_, __LINE__)(name, description); \
    const ::xcrack::Plugins::Registration<interface<3>, classname<3>>      \
      XCRACK_PLUGIN_CONCAT(registration_3d_, __LINE__)(name, description); \
  }

#endif
