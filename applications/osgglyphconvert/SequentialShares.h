/* osgglyphconvert: reading a file larger than memory one share at a time, with the mapping of
 * the whole file. */

#ifndef OSGGLYPHCONVERT_SEQUENTIALSHARES_H
#define OSGGLYPHCONVERT_SEQUENTIALSHARES_H 1

#include <osgGlyphsData/PointShare>

#include <string>
#include <vector>

/** The reduction of shares of a dataset that one process reads one after another (each of them
 * through PointReadOptions::share), for the collective calls of GlyphMapper::prepare() and
 * unifyShares().
 *
 * A process cannot combine a value over shares it has not read yet, so the shares are read in
 * passes: each pass records what every share gives each call and answers each call with the
 * combination of what the previous pass recorded for it. A pass that records exactly what the
 * previous one did has had every answer that processes holding all shares at once would have got:
 * what a share gives a call depends only on the answers to earlier calls. A mapping that combines
 * nothing (radius and range given) converges in one pass; the default radius, whose samples depend
 * on counts over the shares, in four. */
class SequentialShares : public osgGlyphsData::ShareReduction
{
public:
    explicit SequentialShares(unsigned int shares) : _shares(shares) {}

    /** Starts reading share index in the current pass. */
    void beginShare(unsigned int index);
    /** False once the current pass has given a call other values than the previous pass did,
     * or made a call it did not: then the pass is not the last. */
    bool isSettled() const { return _settled; }
    /** Ends a pass over every share; true when every answer of the pass was the final one. */
    bool endPass();

    void minimum(std::vector<double>& values) const override;
    void maximum(std::vector<double>& values) const override;
    void sum(std::vector<double>& values) const override;
    void gather(std::vector<double>& values) const override;
    void gather(std::vector<std::string>& strings) const override;
    osgGlyphsData::PointShare getShare() const override;

protected:
    ~SequentialShares() override = default;

private:
    enum class Kind
    {
        Minimum,
        Maximum,
        Sum,
        GatherValues,
        GatherStrings
    };
    /** What each share gave one call, in share order. */
    struct Call
    {
        Kind kind;
        std::vector<std::vector<double>> values;
        std::vector<std::vector<std::string>> strings;
        bool operator==(const Call& other) const
        {
            return kind == other.kind && values == other.values && strings == other.strings;
        }
    };

    /** Records the call's values and returns the previous pass's record of it, if of this kind
     * and of as many values from every share. */
    const Call* record(Kind kind, const std::vector<double>* values,
                       const std::vector<std::string>* strings) const;
    void combine(Kind kind, std::vector<double>& values) const;

    unsigned int _shares;
    unsigned int _index = 0;
    mutable std::size_t _next = 0; // the share's next call
    mutable std::vector<Call> _recording;
    std::vector<Call> _previous;
    mutable bool _settled = true;
};

#endif
