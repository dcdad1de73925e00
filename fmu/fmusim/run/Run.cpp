#include "Subcommands.hpp"

#include "io/Args.hpp"
#include "io/Csv.hpp"
#include "Errors.hpp"
#include "Session.hpp"
#include "io/Settings.hpp"
#include "io/Values.hpp"

#include <climits>
#include <cmath>
#include <optional>

namespace fmusim {

const char* runUsage()
{
    return "fmusim run model.fmu [options]\n"
           "  Simulates an FMI 2.0 co-simulation FMU with fixed communication steps.\n"
           "  --start-time T0         default: DefaultExperiment startTime, else 0\n"
           "  --stop-time T1          default: DefaultExperiment stopTime, else T0 + 1\n"
           "  --step-size H           default: DefaultExperiment stepSize, else (T1 - T0)/500\n"
           "  --set name=value        set a parameter, an input or a variable with a start value\n"
           "                          (initial exact or approx) before initialization (repeatable)\n"
           "  --parameters file       'name = value' per line, '#' comments; --set wins\n"
           "  --input-file in.csv     header: time, then input names; Real inputs are\n"
           "                          interpolated linearly, others take the last row at or\n"
           "                          before t; the first and last rows hold outside the table\n"
           "  --output-file out.csv   default: standard output\n"
           "  --output-variables a,b  default: every output\n"
           "  --logging               switch on the FMU's debug logging\n"
           "  --timeout SECONDS       end the run (exit code 6) when one call into the FMU\n"
           "                          takes longer; default 0: no limit\n"
           "  --isolation none|process\n"
           "                          none (default): the FMU runs in fmusim's process; process:\n"
           "                          in a process of its own, so that a crash or exit() of the\n"
           "                          FMU ends the run with exit code 7 and a message naming the\n"
           "                          call, as a time-out does (exit code 6)\n"
           "  Before fmi2DoStep(t, h) the inputs are set to their values at t + h, and the\n"
           "  row for t + h is written after it (the connector interface's convention).\n"
           "  A NaN or infinite value in a Real column stops the run (exit code 5).\n"
           "  An FMU that asks to end the simulation (fmi2Discard, fmi2Terminated) ends\n"
           "  the run there (exit code 0); a step discarded otherwise is exit code 5.\n";
}

namespace {

struct InputColumn {
    std::size_t column;
    const fmuImport::Variable* variable;
};

struct RunOptions {
    std::string fmuPath;
    std::optional<double> startTime, stopTime, stepSize;
    std::vector<Setting> settings;
    std::string inputFile, outputFile;
    std::optional<std::string> outputVariables;
    bool logging = false;
    double timeout = 0; // [s], 0: none
    fmuImport::Isolation isolation = fmuImport::Isolation::none;
};

RunOptions parseRunOptions(const std::vector<std::string>& arguments)
{
    const Args args = parseArgs(arguments,
                                {"start-time", "stop-time", "step-size", "set",
                                 "parameters", "input-file", "output-file",
                                 "output-variables", "timeout", "isolation"},
                                {"logging"});
    if (args.positional.size() != 1)
        throw UsageError("run needs exactly one FMU file");
    RunOptions o;
    o.fmuPath = args.positional[0];
    o.startTime = args.number("start-time");
    o.stopTime = args.number("stop-time");
    o.stepSize = args.number("step-size");
    if (o.stepSize && !(*o.stepSize > 0))
        throw UsageError("--step-size must be positive");
    o.settings = fmuSettings(args);
    o.inputFile = args.last("input-file").value_or("");
    o.outputFile = args.last("output-file").value_or("");
    o.outputVariables = args.last("output-variables");
    o.logging = args.flag("logging");
    o.timeout = timeoutOption(args);
    o.isolation = isolationOption(args);
    return o;
}

std::vector<InputColumn> matchInputs(const fmuImport::Fmu& fmu,
                                     const InputTable& table)
{
    std::vector<InputColumn> columns;
    const std::string where = table.path() + ":"
        + std::to_string(table.headerLine()) + ": column '";
    for (std::size_t i = 0; i < table.names().size(); ++i) {
        const std::string& name = table.names()[i];
        if (!fmu.hasVariable(name))
            throw FileError(where + name + "': FMU '" + fmu.path()
                            + "' has no variable '" + name + "'");
        const fmuImport::Variable& v = fmu.variable(name);
        if (v.causality != fmuImport::Causality::input)
            throw FileError(where + name + "': the variable is not an input");
        if (v.type == fmuImport::Type::String)
            throw FileError(where + name
                            + "': String inputs cannot come from a table");
        columns.push_back({i, &v});
    }
    return columns;
}

void setInputs(fmuImport::Instance& instance, const InputTable* table,
               const std::vector<InputColumn>& columns, double t)
{
    std::vector<unsigned int> realVrs, intVrs, boolVrs;
    std::vector<double> reals;
    std::vector<int> ints;
    std::vector<bool> bools;
    for (const InputColumn& c : columns) {
        switch (c.variable->type) {
        case fmuImport::Type::Real:
            realVrs.push_back(c.variable->valueReference);
            reals.push_back(table->interpolate(c.column, t));
            break;
        case fmuImport::Type::Boolean:
            boolVrs.push_back(c.variable->valueReference);
            bools.push_back(table->previous(c.column, t) != 0);
            break;
        default: {
            // Integer values are ints (fmuImport): an FMI 3.0 Int64,
            // UInt32 or UInt64 value beyond int's range is refused, not
            // wrapped
            const double value = std::round(table->previous(c.column, t));
            if (!(value >= INT_MIN && value <= INT_MAX))
                throw FileError(table->path() + ": column '" + c.variable->name
                                + "': " + formatNumber(value)
                                + " at t = " + formatNumber(t)
                                + " is beyond the range of fmusim's Integer "
                                  "values (int, 32 bits)");
            intVrs.push_back(c.variable->valueReference);
            ints.push_back(static_cast<int>(value));
        }
        }
    }
    if (!realVrs.empty())
        instance.setReal(realVrs, reals);
    if (!intVrs.empty())
        instance.setInteger(intVrs, ints);
    if (!boolVrs.empty())
        instance.setBoolean(boolVrs, bools);
}

std::vector<const fmuImport::Variable*>
outputVariables(const fmuImport::Fmu& fmu, const RunOptions& o)
{
    if (!o.outputVariables)
        return outputsOf(fmu);
    std::vector<const fmuImport::Variable*> chosen;
    for (const std::string& name : splitNames(*o.outputVariables)) {
        if (!fmu.hasVariable(name))
            throw UsageError("--output-variables: FMU '" + fmu.path()
                             + "' has no variable '" + name + "'");
        chosen.push_back(&fmu.variable(name));
    }
    return chosen;
}

} // namespace

int runCommand(const std::vector<std::string>& arguments)
{
    const RunOptions o = parseRunOptions(arguments);
    const fmuImport::Fmu fmu
        = loadFmu(o.fmuPath, {o.isolation, o.timeout, std::string()});
    const fmuImport::ModelDescription& md = fmu.modelDescription();

    const double t0
        = o.startTime.value_or(md.hasDefaultExperiment ? md.startTime : 0.0);
    double t1 = o.stopTime.value_or(
        md.hasDefaultExperiment && md.stopTime > t0 ? md.stopTime : t0 + 1.0);
    if (!(t1 > t0))
        throw UsageError("the stop time " + formatNumber(t1)
                         + " is not after the start time " + formatNumber(t0));
    const double h = o.stepSize.value_or(
        md.hasDefaultExperiment && md.stepSize > 0 ? md.stepSize
                                                   : (t1 - t0) / 500);
    const long steps = static_cast<long>(std::ceil((t1 - t0) / h - 1e-9));

    std::optional<InputTable> table;
    std::vector<InputColumn> columns;
    if (!o.inputFile.empty()) {
        table.emplace(o.inputFile);
        columns = matchInputs(fmu, *table);
    }
    const std::vector<const fmuImport::Variable*> outputs
        = outputVariables(fmu, o);

    fmuImport::Instance instance = instantiate(
        fmu, md.modelIdentifier, stderrLogger(o.logging), o.logging);
    instance.setupExperiment(t0, true, t1);
    applySettings(fmu, instance, o.settings);
    instance.enterInitializationMode();
    if (table)
        setInputs(instance, &*table, columns, t0);
    instance.exitInitializationMode();

    CsvWriter out(o.outputFile);
    std::vector<std::string> header {"time"};
    for (const fmuImport::Variable* v : outputs)
        header.push_back(csvField(v->name));
    out.row(header);

    auto writeRow = [&](double t) {
        std::vector<std::string> row {formatNumber(t)};
        const std::vector<std::string> values = readValues(instance, outputs);
        row.insert(row.end(), values.begin(), values.end());
        out.row(row);
    };
    writeRow(t0);
    for (long k = 0; k < steps; ++k) {
        const double t = t0 + k * h;
        const double next = k + 1 == steps ? t1 : t0 + (k + 1) * h;
        if (table)
            setInputs(instance, &*table, columns, next);
        if (!stepOrEnd(instance, t, next - t)) {
            // Outputs of the last successful time, if the FMU got past t
            const double reached = instance.lastSuccessfulTime();
            if (reached > t)
                writeRow(reached);
            break;
        }
        writeRow(next);
    }
    instance.terminate();
    out.finish();
    return exitOk;
}

} // namespace fmusim
