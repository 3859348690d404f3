// ======================================================================
// \title  Uplink.hpp
// \brief  Scripted command uplink into the command dispatcher
// ======================================================================
#ifndef KIT_UPLINK_HPP
#define KIT_UPLINK_HPP

#include "app/Components/Uplink/UplinkComponentAc.hpp"

namespace Kit {

class Uplink final : public UplinkComponentBase {
  public:
    static constexpr FwSizeType FRAME_MAX = 16;   //!< bytes in one frame
    static constexpr FwSizeType SCRIPT_MAX = 16;  //!< frames in one script

    //! One uplinked frame: raw bytes, sent at a given 10 Hz cycle
    struct Frame {
        U32 cycle;
        U8 size;
        U8 bytes[FRAME_MAX];
    };

    //! What happened to a frame
    struct FrameResult {
        bool sent;
        bool answered;
        FwOpcodeType opcode;
        Fw::CmdResponse response;
    };

    //! Build a well-formed command frame: descriptor, opcode, argument bytes
    static Frame commandFrame(U32 cycle, FwOpcodeType opcode, const U8* args, FwSizeType argSize);

    explicit Uplink(const char* const compName);
    ~Uplink();

    //! Script to play; the array must outlive the component
    void configure(const Frame* frames, FwSizeType count);

    FwSizeType frameCount() const { return m_count; }
    const FrameResult& result(FwSizeType index) const;

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    void cmdResponseIn_handler(FwIndexType portNum,
                               FwOpcodeType opCode,
                               U32 cmdSeq,
                               const Fw::CmdResponse& response) override;

    const Frame* m_frames;
    FwSizeType m_count;
    FrameResult m_results[SCRIPT_MAX];
    U32 m_cycle;
    U32 m_sent;
    U32 m_rejected;
};

}  // namespace Kit

#endif
