#include <osgGlyphsComposite/MPIShare>

#include <mpi.h>

#include <cstdlib>

using namespace osgGlyphsComposite;

namespace
{

int liveShares = 0;

void reduce(std::vector<double>& values, MPI_Op operation)
{
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, operation,
                  MPI_COMM_WORLD);
}

/** The concatenation of every process's values, in rank order (the sizes may differ). */
template <typename T>
std::vector<T> gatherAll(const std::vector<T>& values, MPI_Datatype type, int size)
{
    int count = static_cast<int>(values.size());
    std::vector<int> counts(size), offsets(size);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int rank = 0; rank < size; ++rank)
    {
        offsets[rank] = total;
        total += counts[rank];
    }
    std::vector<T> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(values.data(), count, type, all.data(), counts.data(), offsets.data(), type,
                   MPI_COMM_WORLD);
    return all;
}

}

bool osgGlyphsComposite::isLaunchedByMPI()
{
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    {
        if (std::getenv(variable))
            return true;
    }
    return false;
}

MPIShare::MPIShare()
{
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized)
    {
        MPI_Init(nullptr, nullptr);
        _initializedHere = true;
    }
    ++liveShares;
    MPI_Comm_rank(MPI_COMM_WORLD, &_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &_size);
}

MPIShare::~MPIShare()
{
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (--liveShares == 0 && _initializedHere && !finalized)
        MPI_Finalize();
}

osgGlyphsData::PointShare MPIShare::getShare() const
{
    return osgGlyphsData::PointShare{static_cast<unsigned int>(_rank), static_cast<unsigned int>(_size)};
}

void MPIShare::minimum(std::vector<double>& values) const
{
    reduce(values, MPI_MIN);
}

void MPIShare::maximum(std::vector<double>& values) const
{
    reduce(values, MPI_MAX);
}

void MPIShare::sum(std::vector<double>& values) const
{
    // Gathered and added in rank order, so that every process gets the same rounding.
    std::vector<double> all = values;
    gather(all);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        double total = 0.0;
        for (int rank = 0; rank < _size; ++rank)
            total += all[rank * values.size() + i];
        values[i] = total;
    }
}

void MPIShare::gather(std::vector<double>& values) const
{
    values = gatherAll(values, MPI_DOUBLE, _size);
}

void MPIShare::gather(std::vector<std::string>& strings) const
{
    std::vector<int> lengths;
    std::vector<char> characters;
    for (const std::string& text : strings)
    {
        lengths.push_back(static_cast<int>(text.size()));
        characters.insert(characters.end(), text.begin(), text.end());
    }
    lengths = gatherAll(lengths, MPI_INT, _size);
    characters = gatherAll(characters, MPI_CHAR, _size);
    strings.clear();
    std::size_t start = 0;
    for (int length : lengths)
    {
        strings.emplace_back(characters.data() + start, static_cast<std::size_t>(length));
        start += static_cast<std::size_t>(length);
    }
}

bool MPIShare::agree(bool ok, std::string& error) const
{
    int failed = ok ? _size : _rank;
    MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (failed == _size)
        return true;
    int length = failed == _rank ? static_cast<int>(error.size()) : 0;
    MPI_Bcast(&length, 1, MPI_INT, failed, MPI_COMM_WORLD);
    error.resize(static_cast<std::size_t>(length));
    MPI_Bcast(error.data(), length, MPI_CHAR, failed, MPI_COMM_WORLD);
    return false;
}

double MPIShare::getMaximum(double value) const
{
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return value;
}
