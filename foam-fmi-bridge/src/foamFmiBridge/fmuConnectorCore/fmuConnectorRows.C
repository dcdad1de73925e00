// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorRows.H"
#include "fmuImport/fmuImport.hpp"

#include <algorithm>
#include <cerrno>
#include <cfenv>
#include <ctime>
#include <thread>
#include <pthread.h>
#include <semaphore.h>
#include <signal.h>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Bytes of the ring of a connector: about 8000 rows of a spring's 17
//  numbers, at least 64 rows
constexpr size_t ringBytes = 1 << 20;

//- How long the writer collects rows [ns]
constexpr long periodNs = 2000000;

//- The process's writer thread and the rows it writes. Never destroyed:
//  the thread and the ending hook may run after static destructors
struct writer
{
    //- The rows of every connector, and one pass of the writer over them
    std::mutex mutex;
    std::vector<Foam::fmuConnectorRows*> rows;

    //- Posted when a row is published while the writer sleeps, when a
    //  ring is half full, or when the process is ending
    sem_t wake;

    //- Whether the writer waits for wake (taken back by whoever posts)
    std::atomic<bool> sleeping{true};

    //- Whether the process is ending, or a ring is half full: write at
    //  once
    std::atomic<bool> urgent{false};

    //- Rows published and rows written (or dropped), of every connector
    std::atomic<std::uint64_t> published{0};
    std::atomic<std::uint64_t> written{0};
};

std::atomic<writer*> theWriter{nullptr};


void sleepNs(const long ns)
{
    const timespec t{0, ns};
    ::nanosleep(&t, nullptr);
}


//- Write every published row of every connector
void writeAll(writer& w)
{
    const std::lock_guard<std::mutex> lock(w.mutex);
    for (Foam::fmuConnectorRows* rows : w.rows)
    {
        rows->drain();
    }
}


//- The writer thread: sleeps until a row is published, collects rows for
//  a period, writes them, and sleeps again once none is left
void run(writer& w)
{
    // Formatting raises no flag worth a trap
    fedisableexcept(FE_ALL_EXCEPT);

    for (;;)
    {
        while (::sem_wait(&w.wake) != 0)
        {}

        // Collect rows for a period, unless hurried (one wake-up: the
        // writer shares a core with the solver on a busy machine)
        timespec deadline;
        ::clock_gettime(CLOCK_REALTIME, &deadline);
        deadline.tv_nsec += periodNs;
        if (deadline.tv_nsec >= 1000000000)
        {
            deadline.tv_sec += 1;
            deadline.tv_nsec -= 1000000000;
        }
        while (!w.urgent.load() && ::sem_timedwait(&w.wake, &deadline) != 0)
        {
            if (errno == ETIMEDOUT)
            {
                break;
            }
        }
        for (;;)
        {
            w.urgent.store(false);
            writeAll(w);
            // Sleep unless rows came meanwhile and no one has posted wake
            // for them yet (seq_cst: a publisher sees sleeping, or this
            // sees its row)
            w.sleeping.store(true);
            if
            (
                w.written.load() >= w.published.load()
             || !w.sleeping.exchange(false)
            )
            {
                break;
            }
        }
    }
}


//- fmuImport's ending hook: the process ends without its exit handlers
//  (a signal, a time-out). Async-signal-safe: atomics, sem_post, nanosleep
void waitForWriter()
{
    writer* w = theWriter.load();
    if (!w)
    {
        return;
    }
    const std::uint64_t target = w->published.load();
    if (w->written.load() >= target)
    {
        return;
    }
    // Wakes the writer, asleep or collecting
    w->urgent.store(true);
    w->sleeping.store(false);
    ::sem_post(&w->wake);
    // At most a second: the writer may wait for a lock this thread holds
    for (int i = 0; i < 10000 && w->written.load() < target; ++i)
    {
        sleepNs(100000);
    }
}


//- The writer, started at the first call, with every signal blocked
writer& startedWriter()
{
    static writer* const w = []()
    {
        writer* created = new writer;
        ::sem_init(&created->wake, 0, 0);

        sigset_t all, previous;
        sigfillset(&all);
        ::pthread_sigmask(SIG_SETMASK, &all, &previous);
        std::thread(run, std::ref(*created)).detach();
        ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);

        theWriter.store(created);
        fmuImport::setEndingHook(waitForWriter);
        return created;
    }();
    return *w;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

double Foam::fmuConnectorRows::period()
{
    return 1e-9*periodNs;
}


void Foam::fmuConnectorRows::drainAll()
{
    if (writer* w = theWriter.load())
    {
        writeAll(*w);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

int Foam::fmuConnectorRows::writeRows()
{
    const std::uint64_t head = head_.load(std::memory_order_acquire);
    const std::uint64_t tail = tail_.load(std::memory_order_relaxed);
    if (head == tail)
    {
        return error_.load(std::memory_order_relaxed);
    }

    if (!error_.load(std::memory_order_relaxed))
    {
        // Room for each number and its separator
        text_.resize((head - tail)*width_*rowFile::maxNumberChars);
        char* c = &text_[0];
        for (std::uint64_t r = tail; r < head; ++r)
        {
            const double* row = &ring_[(r % capacity_)*width_];
            for (size_t i = 0; i < width_; ++i)
            {
                c = rowFile::writeNumber(c, row[i]);
                *c++ = ' ';
            }
            c[-1] = '\n';
        }
        text_.resize(c - &text_[0]);

        const off_t before = file_.size();
        const int error = file_.tryAppend(text_);
        if (error)
        {
            // The first row not written whole begins where the file ends
            const size_t at = size_t(file_.size() - before);
            failedRow_ =
                "the row of t = "
              + text_.substr(at, text_.find_first_of(" \n", at) - at)
              + " s of connector " + name_;
            error_.store(error, std::memory_order_release);
        }
    }

    // Written, or dropped after a failure
    tail_.store(head, std::memory_order_release);
    theWriter.load()->written.fetch_add(head - tail);
    return error_.load(std::memory_order_relaxed);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fmuConnectorRows::fmuConnectorRows
(
    rowFile& file,
    const word& name,
    const label width
)
:
    file_(file),
    name_(name),
    width_(width),
    capacity_(std::max<size_t>(64, ringBytes/(sizeof(double)*width))),
    ring_(capacity_*width_),
    head_(0),
    tail_(0),
    error_(0)
{
    writer& w = startedWriter();
    const std::lock_guard<std::mutex> lock(w.mutex);
    w.rows.push_back(this);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fmuConnectorRows::~fmuConnectorRows()
{
    writer& w = *theWriter.load();
    const std::lock_guard<std::mutex> lock(w.mutex);
    w.rows.erase(std::find(w.rows.begin(), w.rows.end(), this));

    // Rows left unwritten count as done for the ending hook
    w.written.fetch_add(head_.load() - tail_.load());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

double* Foam::fmuConnectorRows::next()
{
    const std::uint64_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) >= capacity_)
    {
        drain();
    }
    return &ring_[(head % capacity_)*width_];
}


void Foam::fmuConnectorRows::publish()
{
    head_.store
    (
        head_.load(std::memory_order_relaxed) + 1,
        std::memory_order_release
    );

    writer& w = *theWriter.load(std::memory_order_relaxed);
    w.published.fetch_add(1);
    if (w.sleeping.load() && w.sleeping.exchange(false))
    {
        ::sem_post(&w.wake);
    }
    else if
    (
        2*(head_.load(std::memory_order_relaxed) - tail_.load()) > capacity_
     && !w.urgent.load(std::memory_order_relaxed)
     && !w.urgent.exchange(true)
    )
    {
        // Half full: the writer stops collecting
        ::sem_post(&w.wake);
    }
}


int Foam::fmuConnectorRows::drain()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return writeRows();
}


// ************************************************************************* //
