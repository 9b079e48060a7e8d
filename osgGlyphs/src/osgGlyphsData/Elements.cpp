#include <osgGlyphsData/Elements>

#include <cctype>

using namespace osgGlyphsData;

namespace
{

// number, symbol, name, covalent radius, van der Waals radius, Jmol colour.
const Element table[] = {
    {1, "H", "Hydrogen", 0.31f, 1.20f, 0xFFFFFF},       {2, "He", "Helium", 0.28f, 1.40f, 0xD9FFFF},
    {3, "Li", "Lithium", 1.28f, 1.82f, 0xCC80FF},       {4, "Be", "Beryllium", 0.96f, 1.53f, 0xC2FF00},
    {5, "B", "Boron", 0.84f, 1.92f, 0xFFB5B5},          {6, "C", "Carbon", 0.76f, 1.70f, 0x909090},
    {7, "N", "Nitrogen", 0.71f, 1.55f, 0x3050F8},       {8, "O", "Oxygen", 0.66f, 1.52f, 0xFF0D0D},
    {9, "F", "Fluorine", 0.57f, 1.47f, 0x90E050},       {10, "Ne", "Neon", 0.58f, 1.54f, 0xB3E3F5},
    {11, "Na", "Sodium", 1.66f, 2.27f, 0xAB5CF2},       {12, "Mg", "Magnesium", 1.41f, 1.73f, 0x8AFF00},
    {13, "Al", "Aluminium", 1.21f, 1.84f, 0xBFA6A6},    {14, "Si", "Silicon", 1.11f, 2.10f, 0xF0C8A0},
    {15, "P", "Phosphorus", 1.07f, 1.80f, 0xFF8000},    {16, "S", "Sulfur", 1.05f, 1.80f, 0xFFFF30},
    {17, "Cl", "Chlorine", 1.02f, 1.75f, 0x1FF01F},     {18, "Ar", "Argon", 1.06f, 1.88f, 0x80D1E3},
    {19, "K", "Potassium", 2.03f, 2.75f, 0x8F40D4},     {20, "Ca", "Calcium", 1.76f, 2.31f, 0x3DFF00},
    {21, "Sc", "Scandium", 1.70f, 2.58f, 0xE6E6E6},     {22, "Ti", "Titanium", 1.60f, 2.46f, 0xBFC2C7},
    {23, "V", "Vanadium", 1.53f, 2.42f, 0xA6A6AB},      {24, "Cr", "Chromium", 1.39f, 2.45f, 0x8A99C7},
    {25, "Mn", "Manganese", 1.39f, 2.45f, 0x9C7AC7},    {26, "Fe", "Iron", 1.32f, 2.44f, 0xE06633},
    {27, "Co", "Cobalt", 1.26f, 2.40f, 0xF090A0},       {28, "Ni", "Nickel", 1.24f, 1.63f, 0x50D050},
    {29, "Cu", "Copper", 1.32f, 1.40f, 0xC88033},       {30, "Zn", "Zinc", 1.22f, 1.39f, 0x7D80B0},
    {31, "Ga", "Gallium", 1.22f, 1.87f, 0xC28F8F},      {32, "Ge", "Germanium", 1.20f, 2.11f, 0x668F8F},
    {33, "As", "Arsenic", 1.19f, 1.85f, 0xBD80E3},      {34, "Se", "Selenium", 1.20f, 1.90f, 0xFFA100},
    {35, "Br", "Bromine", 1.20f, 1.85f, 0xA62929},      {36, "Kr", "Krypton", 1.16f, 2.02f, 0x5CB8D1},
    {37, "Rb", "Rubidium", 2.20f, 3.03f, 0x702EB0},     {38, "Sr", "Strontium", 1.95f, 2.49f, 0x00FF00},
    {39, "Y", "Yttrium", 1.90f, 2.75f, 0x94FFFF},       {40, "Zr", "Zirconium", 1.75f, 2.52f, 0x94E0E0},
    {41, "Nb", "Niobium", 1.64f, 2.56f, 0x73C2C9},      {42, "Mo", "Molybdenum", 1.54f, 2.45f, 0x54B5B5},
    {43, "Tc", "Technetium", 1.47f, 2.44f, 0x3B9E9E},   {44, "Ru", "Ruthenium", 1.46f, 2.46f, 0x248F8F},
    {45, "Rh", "Rhodium", 1.42f, 2.44f, 0x0A7D8C},      {46, "Pd", "Palladium", 1.39f, 1.63f, 0x006985},
    {47, "Ag", "Silver", 1.45f, 1.72f, 0xC0C0C0},       {48, "Cd", "Cadmium", 1.44f, 1.58f, 0xFFD98F},
    {49, "In", "Indium", 1.42f, 1.93f, 0xA67573},       {50, "Sn", "Tin", 1.39f, 2.17f, 0x668080},
    {51, "Sb", "Antimony", 1.39f, 2.06f, 0x9E63B5},     {52, "Te", "Tellurium", 1.38f, 2.06f, 0xD47A00},
    {53, "I", "Iodine", 1.39f, 1.98f, 0x940094},        {54, "Xe", "Xenon", 1.40f, 2.16f, 0x429EB0},
    {55, "Cs", "Caesium", 2.44f, 3.43f, 0x57178F},      {56, "Ba", "Barium", 2.15f, 2.68f, 0x00C900},
    {57, "La", "Lanthanum", 2.07f, 2.98f, 0x70D4FF},    {58, "Ce", "Cerium", 2.04f, 2.88f, 0xFFFFC7},
    {59, "Pr", "Praseodymium", 2.03f, 2.92f, 0xD9FFC7}, {60, "Nd", "Neodymium", 2.01f, 2.95f, 0xC7FFC7},
    {61, "Pm", "Promethium", 1.99f, 2.90f, 0xA3FFC7},   {62, "Sm", "Samarium", 1.98f, 2.90f, 0x8FFFC7},
    {63, "Eu", "Europium", 1.98f, 2.87f, 0x61FFC7},     {64, "Gd", "Gadolinium", 1.96f, 2.83f, 0x45FFC7},
    {65, "Tb", "Terbium", 1.94f, 2.79f, 0x30FFC7},      {66, "Dy", "Dysprosium", 1.92f, 2.87f, 0x1FFFC7},
    {67, "Ho", "Holmium", 1.92f, 2.81f, 0x00FF9C},      {68, "Er", "Erbium", 1.89f, 2.83f, 0x00E675},
    {69, "Tm", "Thulium", 1.90f, 2.79f, 0x00D452},      {70, "Yb", "Ytterbium", 1.87f, 2.80f, 0x00BF38},
    {71, "Lu", "Lutetium", 1.87f, 2.74f, 0x00AB24},     {72, "Hf", "Hafnium", 1.75f, 2.63f, 0x4DC2FF},
    {73, "Ta", "Tantalum", 1.70f, 2.53f, 0x4DA6FF},     {74, "W", "Tungsten", 1.62f, 2.57f, 0x2194D6},
    {75, "Re", "Rhenium", 1.51f, 2.49f, 0x267DAB},      {76, "Os", "Osmium", 1.44f, 2.48f, 0x266696},
    {77, "Ir", "Iridium", 1.41f, 2.41f, 0x175487},      {78, "Pt", "Platinum", 1.36f, 1.75f, 0xD0D0E0},
    {79, "Au", "Gold", 1.36f, 1.66f, 0xFFD123},         {80, "Hg", "Mercury", 1.32f, 1.55f, 0xB8B8D0},
    {81, "Tl", "Thallium", 1.45f, 1.96f, 0xA6544D},     {82, "Pb", "Lead", 1.46f, 2.02f, 0x575961},
    {83, "Bi", "Bismuth", 1.48f, 2.07f, 0x9E4FB5},      {84, "Po", "Polonium", 1.40f, 1.97f, 0xAB5C00},
    {85, "At", "Astatine", 1.50f, 2.02f, 0x754F45},     {86, "Rn", "Radon", 1.50f, 2.20f, 0x428296},
    {87, "Fr", "Francium", 2.60f, 3.48f, 0x420066},     {88, "Ra", "Radium", 2.21f, 2.83f, 0x007D00},
    {89, "Ac", "Actinium", 2.15f, 2.80f, 0x70ABFA},     {90, "Th", "Thorium", 2.06f, 2.93f, 0x00BAFF},
    {91, "Pa", "Protactinium", 2.00f, 2.88f, 0x00A1FF}, {92, "U", "Uranium", 1.96f, 1.86f, 0x008FFF},
    {93, "Np", "Neptunium", 1.90f, 2.82f, 0x0080FF},    {94, "Pu", "Plutonium", 1.87f, 2.81f, 0x006BFF},
};

const unsigned int tableSize = sizeof(table) / sizeof(table[0]);

const Element unknown = {0, "X", "Unknown", 0.75f, 1.70f, 0xFF1493};

} // namespace

unsigned int osgGlyphsData::getMaxAtomicNumber()
{
    return tableSize;
}

const Element& osgGlyphsData::getElement(unsigned int atomicNumber)
{
    if (atomicNumber == 0 || atomicNumber > tableSize)
        return unknown;
    return table[atomicNumber - 1];
}

const Element* osgGlyphsData::findElement(const std::string& symbol)
{
    std::size_t begin = 0;
    std::size_t end = symbol.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(symbol[begin])))
        ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(symbol[end - 1])))
        --end;
    if (end - begin < 1 || end - begin > 2)
        return nullptr;
    char wanted[3] = {0, 0, 0};
    wanted[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(symbol[begin])));
    if (end - begin == 2)
        wanted[1] = static_cast<char>(std::tolower(static_cast<unsigned char>(symbol[begin + 1])));
    for (const Element& element : table)
    {
        if (element.symbol[0] == wanted[0] && element.symbol[1] == wanted[1])
            return &element;
    }
    return nullptr;
}

const Element& osgGlyphsData::getUnknownElement()
{
    return unknown;
}

const Element& osgGlyphsData::getElementBySymbol(const std::string& symbol)
{
    const Element* element = findElement(symbol);
    return element ? *element : unknown;
}
